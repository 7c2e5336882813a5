"""Whether an h_stop case's outcome belongs to the simulation or to its one realisation: the
cases of the staircase farthest on the wrong side of the paper's curve run again from other
random fillings (run.seed), and from the first filling with half the time step (t_c / 100,
against the paper's t_c / 50), each to t = 500 under the arrest test of Sect. 6:
- H = 8 arrested at 23°, where Weinhart et al. 2012's Eq. 35 puts theta_stop at 22.74°;
- H = 28 arrested at 20°, 0.31° above the curve at its h = 24.8, the farthest of the thick layers.
If halving the time step turns an arrest into a flow, the staircase's arrests are the time
step's as much as the layer's."""
import math
from pathlib import Path

from validation_closures import case_folder, froude_error, kept_rows

CONTACT_TIME = 0.0049711793850625635  # examples/chute.toml: k_n = 2e5, damping rate 50, m = 1 (Eqs. 5-6)
HALF_STEP = "run.time_step=%r" % (CONTACT_TIME / 100)
# (H, angle), and per variant: its study folder (weinhart2012/<name>), label and overrides.
CASES = [({"H": 8, "angle": 23}, [("hstop_seed2", "filling seed 2", ["run.seed=2"]),
                                  ("hstop_seed3", "filling seed 3", ["run.seed=3"]),
                                  ("hstop_dt100", "seed 1, time step t_c / 100", [HALF_STEP])]),
         ({"H": 28, "angle": 20}, [("hstop_H28_dt100", "seed 1, time step t_c / 100", [HALF_STEP]),
                                   ("hstop_H28_seed2", "filling seed 2", ["run.seed=2"])])]


# One steady flow of the map, from the same filling, run again with the base's damping convention of Weinhart et
# al.'s code (validation/weinhart2012/chute_coefficient_damping.toml) and with half the time step, and from two other
# bases and fillings (run.seed: the base settles from seed + 1, the layer is placed from seed): the thin flows lie
# furthest below Table 1's flow rule.
DAMPING_CASE = {"H": 10, "angle": 24}
OTHER_BASES = [("flow_seed2", 2), ("flow_seed3", 3)]


def flow_case_options(sets):
    options = ["--lambda", "1", "--heights", str(DAMPING_CASE["H"]), "--angles", str(DAMPING_CASE["angle"]),
               "--end-time", "500", "--average", "100"]
    for s in sets:
        options += ["--set", s]
    return options


def studies(study_class):
    out = [study_class("damping_coefficient", "flowmap", flow_case_options([]), ["sweep_runs.csv"],
                       scenario="validation/weinhart2012/chute_coefficient_damping.toml"),
           study_class("flow_dt100", "flowmap", flow_case_options([HALF_STEP]), ["sweep_runs.csv"])]
    out += [study_class(name, "flowmap", flow_case_options([f"run.seed={seed}"]), ["sweep_runs.csv"])
            for name, seed in OTHER_BASES]
    for case, variants in CASES:
        for name, _, sets in variants:
            options = ["--lambda", "1", "--heights", str(case["H"]), "--angles", str(case["angle"]), "--end-time", "500",
                       "--average", "20"]
            for s in sets:
                options += ["--set", s]
            out.append(study_class(name, "flowmap", options, ["sweep_runs.csv"]))
    return out


def case_lines(chute_fits, staircase, base: Path, case, variants):
    first = [r for r in staircase if r["H"] == case["H"] and r["angle"] == case["angle"]]
    rows = [("staircase (seed 1, t_c / 50)", first[0] if first else None)]
    for name, label, _ in variants:
        found = kept_rows(chute_fits, base / "weinhart2012" / name)
        rows.append((label, found[0] if found else None))
    out = [f"**One realisation or the simulation?** H = {case['H']} at {case['angle']}° again:", "",
           "| run | outcome | arrest time | h (d) |", "|---|---|---|---|"]
    for label, r in rows:
        if r is None:
            out.append(f"| {label} | not run yet | | |")
            continue
        arrest = r.get("arrest_time")
        arrest = f"{arrest:.0f}" if arrest not in ("", None) else ""
        out.append(f"| {label} | {r['flow_state']} | {arrest} | {r['h']:.2f} |")
    done = [r for _, r in rows if r is not None]
    arrested = sum(1 for r in done if r["flow_state"] == "arrested")
    verb = "arrests" if arrested == 1 else "arrest"
    return out + ["", f"{arrested} of these {len(done)} runs {verb} within t = 500.", ""]


def lines(chute_fits, staircase, base: Path):
    out = []
    for case, variants in CASES:
        out += case_lines(chute_fits, staircase, base, case, variants)
    return out + damping_lines(chute_fits, base)


def damping_lines(chute_fits, base: Path):
    def case(study):
        return [(r, froude_error(case_folder(base, study, r))) for r in kept_rows(chute_fits, base / "weinhart2012" / study)
                if r["H"] == DAMPING_CASE["H"] and r["angle"] == DAMPING_CASE["angle"]]
    # (label, what the variant changes, its runs)
    rows = [("rate 50 per unit reduced mass (chute.toml): 50 against the base; t_c / 50", "", case("flowmap")),
            ("coefficient 25 for every pair (Weinhart et al.'s code); t_c / 50", "the damping convention",
             case("damping_coefficient")),
            ("rate 50 as chute.toml; t_c / 100", "half the time step", case("flow_dt100"))]
    rows += [(f"rate 50; t_c / 50; base and filling from run.seed = {seed}", f"the base and filling of seed {seed}",
              case(name)) for name, seed in OTHER_BASES]
    out = [f"**The base's damping, the time step and the base itself.** H = {DAMPING_CASE['H']} at {DAMPING_CASE['angle']}° from the "
           "same filling unless the row says, to t = 500, averaged over [400, 500]:", "", "| damping; time step; base | state | h (d) | F | K | alpha |",
           "|---|---|---|---|---|---|"]
    for label, _, found in rows:
        if not found:
            out.append(f"| {label} | not run yet | | | | |")
            continue
        r, err = found[0]
        out.append(f"| {label} | {r['flow_state']} | {r['h']:.3f} | {r['froude']:.4f} ± {err:.4f} | {r['K']:.3f} | "
                   f"{r['alpha']:.3f} |")
    # Each variant's F against the first row's, in their combined batch-mean errors.
    changes = []
    if rows[0][2]:
        first, first_err = rows[0][2][0]
        for _, change, found in rows[1:]:
            if found:
                r, err = found[0]
                d, e = r["froude"] - first["froude"], math.hypot(err, first_err)
                changes.append(f"{change} {d:+.4f} ± {e:.4f} ({abs(d) / e:.1f} combined standard errors, "
                               f"{100 * d / first['froude']:+.1f} %)")
    if changes:
        out += ["", "Each change moves F from the first row's by: " + "; ".join(changes) + "."]
    return out + [""]
