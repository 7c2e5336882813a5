"""Huet et al. 2021, Fig. 9 and Sec. V A: which columns of crosses stay standing once the gate
opens. The paper's simulations are intermittent in part of its map: of 44 runs there, 26 stayed
stable and 18 collapsed (Appendix D), the columns of its Table III (validation_table3.py). A column is
stable when its length and height stay within a particle size and at most 1 % of its crosses
moved by more than one (talus' collapse_regime); fractured when its height stays but its front
flowed; collapsed otherwise. Families differ by contact model and gate (validation.py)."""
import math

PAPER_INTERMITTENT = (26, 44)  # stable runs, runs: Huet et al. 2021, Appendix D (Fig. 26)


def model_of(sets):
    """The contact points per part pair and the gate of a family, from its overrides."""
    points = "one" if "contact.manifold=false" in sets else "up to four"
    gate = "removed at t = 0" if "dam_break.gate=removed" in sets else "pulled (43 m/s^2, friction)"
    memory = (", no memory" if "contact.tangential=memoryless" in sets else
              ", no memory from the gate's opening" if "dam_break.collapse_tangential=memoryless" in sets else "")
    warm = ""  # GJK's start matters to the one-point model only; from last step's simplex by default
    if points == "one":
        warm = ", GJK started cold" if "contact.gjk_warm_start=false" in sets else ", GJK from last step's simplex"
    recycled = next((s.split("=")[1] for s in sets if s.startswith("contact.manifold_recycle=")), "0")
    if points != "one" and float(recycled) > 0:
        warm = f", recycled for {float(recycled) * 1e6:g} um"
    return f"{points}{memory}{warm}", gate


def lines(runs_by_family, sets_by_family, widest=2):
    """The report's table: for each cross family, its `widest` widest columns (lowest a), the
    regimes of their runs, the runout ratios and the fraction of crosses displaced."""
    rows, tallies = [], []
    for family, runs in runs_by_family.items():
        if not family.startswith("crosses") or family in ("crosses_large", "crosses_wide", "crosses_table3") or not runs:
            continue
        points, gate = model_of(sets_by_family[family])
        widths = sorted({r["L0"] for r in runs})[-widest:]
        kept = [r for r in runs if r["L0"] in widths]
        tallies.append(f"{family} {sum(r.get('regime') == 'stable' for r in kept)} of {len(kept)}")
        for l0 in widths:
            at = [r for r in runs if r["L0"] == l0]
            regimes = [r.get("regime", "") for r in at]
            counts = ", ".join(f"{regimes.count(g)} {g}" for g in ("stable", "fractured", "collapsed") if g in regimes)
            runout = ", ".join(f"{r['dam_break']['runout_ratio']:.2f}" for r in at)
            moved = ", ".join(f"{r['dam_break'].get('displaced_fraction', math.nan):.3f}" for r in at)
            aspect = sum(r["aspect_ratio"] for r in at) / len(at)
            rows.append(f"| {family} | {points} | {gate} | {l0:.3g} | {aspect:.2f} | {counts} | {runout} | {moved} |")
    if not rows:
        return []
    stable, runs = PAPER_INTERMITTENT
    return ["**Which columns stand** (Fig. 9, Sec. V A). The paper's simulations are intermittent at low "
            f"aspect ratios: {stable} of its {runs} runs there stayed stable. Its crosses touch by one point per "
            "pair of convex parts, and the gate is removed at t = 0 (Sec. III C; the pulled gate only for Figs. "
            "6-7). A run is stable when its front and height stay within a particle size (27 mm) and at most 1 % "
            "of its crosses moved by more than one; fractured when its height stays but more moved. The two widest "
            "columns of each family of 1000 crosses:", "",
            "| family | points per part pair | gate | L0 (m) | a | regimes | (L_inf - L0)/L0 per run | "
            "fraction displaced per run |", "|---|---|---|---|---|---|---|---|"] + rows + [
            "", "Stable runs among these columns: " + "; ".join(tallies) + ".", ""]
