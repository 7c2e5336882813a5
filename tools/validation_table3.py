"""Huet et al. 2021, Table III: which column the paper counted its contacts in.

The paper gives its intermittent columns' wall contacts (79.3 on the ground, 169.2 on the side
walls, 72.8 on the gate) but not their size, and it varied L0, H0 and W0 (Sec. III A). A wall's
contact count is its wetted area times a contact density that the packing sets: ground L0 x W0,
side walls 2 x L0 x H0, gate W0 x H0. With the densities of Talus' columns of the paper's model,
the three counts fix the three lengths:
    L0 = sqrt(G S / 2T),  W0 = sqrt(2 G T / S),  H0 = sqrt(S T / 2G)
where G, S and T are the paper's counts over the densities. The family `crosses_table3` runs the
column so found, to compare all of Table III at once."""
import math

# Huet et al. 2021, Table III (a), whole space: mean (sigma) over its intermittent runs.
PAPER_WHOLE = {"coordination_points": (8.20, 0.07), "ground_contacts": (79.3, 4.0),
               "side_wall_contacts": (169.2, 5.7), "gate_contacts": (72.8, 4.5)}
# ... and its two sub-regions: the half close to the gate, the quarter close to its top.
PAPER_REGIONS = {"near_gate": {"coordination_points": (8.20, 0.07), "ground_contacts": (39.3, 3.4),
                               "side_wall_contacts": (84.3, 3.6), "gate_contacts": (72.8, 4.5)},
                 "near_gate_top": {"coordination_points": (7.96, 0.11), "ground_contacts": (0.0, 0.0),
                                   "side_wall_contacts": (33.0, 3.4), "gate_contacts": (26.1, 3.4)}}
WALLS = ("ground_contacts", "side_wall_contacts", "gate_contacts")
INFERRED_FROM = "crosses"   # the family of the paper's contact model whose densities are used
FAMILY = "crosses_table3"   # the column found, run
BOX_WIDTH = 0.20            # m, the paper's box (Sec. III A)
GATE_SLOTS = (0.04, 0.08, 0.12, 0.20, 0.30)  # m, where its gate can stand (Sec. III A)


def nearest_slot(L0):
    return min(GATE_SLOTS, key=lambda s: abs(s - L0))


def wetted_areas(L0, W0, H0):
    """Areas of ground, side walls and gate that the column touches (m^2)."""
    return {"ground_contacts": L0 * W0, "side_wall_contacts": 2 * L0 * H0, "gate_contacts": W0 * H0}


def densities(run):
    """Contact points per square metre of each wall before the gate opens, of one run's summary."""
    whole = run.get("dam_break", {}).get("before_gate", {}).get("whole", {})
    if not all(k in whole for k in WALLS):
        return None
    areas = wetted_areas(run["L0"], run["W0"], run["H0"])
    return {k: whole[k] / areas[k] for k in WALLS}


def column_for(counts, rho):
    """(L0, W0, H0) whose wetted areas hold `counts` contacts at densities `rho`."""
    G, S, T = (counts[k] / rho[k] for k in WALLS)
    return math.sqrt(G * S / (2 * T)), math.sqrt(2 * G * T / S), math.sqrt(S * T / (2 * G))


def side_count_at_width(rho, W0):
    """The side walls' count of the column W0 wide whose ground and gate hold the paper's counts."""
    L0 = PAPER_WHOLE["ground_contacts"][0] / (rho["ground_contacts"] * W0)
    H0 = PAPER_WHOLE["gate_contacts"][0] / (rho["gate_contacts"] * W0)
    return rho["side_wall_contacts"] * wetted_areas(L0, W0, H0)["side_wall_contacts"]


def mean_sem(values):
    n = len(values)
    m = sum(values) / n
    sem = math.sqrt(sum((v - m) ** 2 for v in values) / (n - 1) / n) if n > 1 else math.nan
    return m, sem


def inferred_column(runs):
    """The paper's Table III column from each run's densities: {length: (mean, standard error)}
    over the runs, and the number of crosses it holds at their number density."""
    cols = []
    for r in runs:
        rho = densities(r)
        if rho is None:
            continue
        L0, W0, H0 = column_for({k: PAPER_WHOLE[k][0] for k in WALLS}, rho)
        crosses = r["particles"] / (r["L0"] * r["W0"] * r["H0"]) * L0 * W0 * H0
        cols.append((L0, W0, H0, crosses, side_count_at_width(rho, BOX_WIDTH)))
    if len(cols) < 2:
        return None
    names = ("L0", "W0", "H0", "crosses", "side_at_box_width")
    return {name: mean_sem([c[i] for c in cols]) for i, name in enumerate(names)} | {"runs": len(cols)}


def top_region_reading(runs):
    """How high the paper's "quarter space close to the top of the gate" starts. Talus reads it as
    the near-gate half above H0 / 2. With wall contacts spread evenly over the height, the share
    of the gate's contacts in the region is 1 - z_min / H0, and the side walls' share half that."""
    paper_gate = PAPER_REGIONS["near_gate_top"]["gate_contacts"][0] / PAPER_WHOLE["gate_contacts"][0]
    paper_side = PAPER_REGIONS["near_gate_top"]["side_wall_contacts"][0] / PAPER_WHOLE["side_wall_contacts"][0]
    before = [r["dam_break"]["before_gate"] for r in runs]
    talus_gate = sum(b["near_gate_top"]["gate_contacts"] for b in before) / sum(b["whole"]["gate_contacts"] for b in before)
    talus_side = (sum(b["near_gate_top"]["side_wall_contacts"] for b in before) /
                  sum(b["whole"]["side_wall_contacts"] for b in before))
    return (f"Near the gate's top the two seem to differ by the region's bounds rather than the packing: the paper's "
            f"region holds {100 * paper_gate:.0f} % of the gate's contacts and {100 * paper_side:.1f} % of the side "
            f"walls', Talus' (above H0 / 2) {100 * talus_gate:.0f} % and {100 * talus_side:.1f} %. With contacts spread "
            f"evenly over the height, the paper's gate share puts its region above {1 - paper_gate:.2f} H0, and "
            f"the side walls' share half of the gate's, {50 * paper_gate:.1f} %, as the paper's {100 * paper_side:.1f} % "
            "does: the paper's quarter seems to start higher than H0 / 2, a bound the paper does not give.")


def cell(m, sd):
    return "-" if m is None else (f"{m:.3g} ({sd:.2g})" if sd is not None and math.isfinite(sd) else f"{m:.3g}")


def lines(runs_by_family):
    """The report's paragraph: the column inferred, and the family run in it beside Table III
    (runs_by_family[FAMILY]: its runs whose gate has opened, finished or not)."""
    found = inferred_column(runs_by_family.get(INFERRED_FROM, []))
    if not found:
        return []
    (L0, L0e), (W0, W0e), (H0, H0e), (n, ne), (side, side_e) = (
        found[k] for k in ("L0", "W0", "H0", "crosses", "side_at_box_width"))
    out = ["**Which column Table III counts.** The paper does not give its Table III columns' sizes. Each wall's "
           "count is its wetted area times a contact density, and the densities of the family `crosses` (the "
           f"paper's model, {found['runs']} runs) turn the paper's three whole-column counts into one column: "
           f"L0 = {L0:.3f} ± {L0e:.3f} m, W0 = {W0:.3f} ± {W0e:.3f} m, H0 = {H0:.3f} ± {H0e:.3f} m "
           f"(a = {H0 / L0:.2f}), {n:.0f} ± {ne:.0f} crosses: near the gate slot L0 = "
           f"{100 * nearest_slot(L0):.0f} cm of the paper's box, narrower than its 20 cm (the paper varied W0), "
           "and near the 1300 crosses of its smallest runs. A column as wide as the box cannot hold all three: the one whose ground and "
           f"gate hold 79.3 and 72.8 contacts would have {side:.0f} ± {side_e:.0f} on its side walls, not 169.2."]
    runs = runs_by_family.get(FAMILY, [])
    if runs:
        out += ["", f"The family `{FAMILY}` runs that column ({len(runs)} runs), beside Table III (a): "
                "mean (σ over the runs).", "",
                "| region | source | coordination | ground | side walls | gate |", "|---|---|---|---|---|---|"]
        for region in ("whole", "near_gate", "near_gate_top"):
            paper = PAPER_WHOLE if region == "whole" else PAPER_REGIONS[region]
            keys = ("coordination_points",) + WALLS
            out.append(f"| {region} | paper | " + " | ".join(cell(*paper[k]) for k in keys) + " |")
            cells = []
            for k in keys:
                v = [r["dam_break"]["before_gate"][region][k] for r in runs
                     if k in r.get("dam_break", {}).get("before_gate", {}).get(region, {})]
                m = sum(v) / len(v) if v else None
                sd = math.sqrt(sum((x - m) ** 2 for x in v) / (len(v) - 1)) if len(v) > 1 else None
                cells.append(cell(m, sd))
            out.append(f"| {region} | Talus | " + " | ".join(cells) + " |")
        whole = [r["dam_break"]["before_gate"]["whole"] for r in runs]
        off = []
        for k in ("coordination_points",) + WALLS:
            m = sum(w[k] for w in whole) / len(whole)
            off.append(f"{k.split('_')[0]} {100 * (m / PAPER_WHOLE[k][0] - 1):+.0f} %")
        out += ["", "Whole column, Talus against the paper: " + ", ".join(off) + "."]
        out += ["", top_region_reading(runs)]
        regimes = [r.get("regime", "") for r in runs if r.get("stop_reason") != "interrupted"]
        if regimes:
            out += ["", f"Its {len(regimes)} finished runs once the gate is removed: " + ", ".join(
                f"{regimes.count(g)} {g}" for g in ("stable", "fractured", "collapsed") if g in regimes) +
                    " (the paper: intermittent, 26 of 44 stable)."]
    return out + [""]
