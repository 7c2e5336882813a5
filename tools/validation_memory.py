"""Huet et al. 2021, Sec. V B and Fig. 19: one settled column collapsing with and without memory in
the tangential contact law. The family `crosses_memoryless` pours and settles each seed exactly as
`crosses` does (same seed, same contact law until the gate opens) and switches to the memoryless
law at the gate's opening (dam_break.collapse_tangential), so that each seed gives a pair of
collapses from one initial microstructure, as the paper's Fig. 19 does.

The paper describes the difference, not numbers: without memory the column's height falls faster,
fewer crosses leave its top, and the bottom slowly deforms and overpacks where it should stay
static. The report gives each pair's observables and the mean paired difference with its
standard error over the seeds."""
import csv
import json
import math
from pathlib import Path

WITH, WITHOUT = "crosses", "crosses_memoryless"
POINT = "gate_position=0.04"


def final_coordination(summary):
    """summary.json's coordination_number is the column's before the gate; contacts is the last record's."""
    return 2 * summary["contacts"] / summary["derived"]["particles"]


# (label, how to read it from a summary.json)
QUANTITIES = [
    ("(L_inf - L0)/L0", lambda s: s["dam_break"]["runout_ratio"]),
    ("H0/H_inf", lambda s: s["dam_break"]["height_ratio"]),
    ("centre-of-mass Delta x / x0", lambda s: s["dam_break"]["com_ratio"]),
    ("fraction of crosses displaced", lambda s: s["dam_break"]["displaced_fraction"]),
    ("collapse duration (s)", lambda s: s["dam_break"]["collapse_duration"]),
    ("coordination at the end (2 x contact points between crosses / crosses)", final_coordination),
]


def finished(run: Path) -> bool:
    """A run that ended by itself (validation.finished)."""
    f = run / "summary.json"
    return f.exists() and json.loads(f.read_text()).get("stop_reason") != "interrupted"


def pairs(base: Path):
    """[(seed, summary with memory, summary without, folder with, folder without)] of the seeds
    both families have finished."""
    out = []
    for without in sorted((base / "huet2021" / WITHOUT / POINT).glob("seed_*")):
        with_ = base / "huet2021" / WITH / POINT / without.name
        if finished(without) and finished(with_):
            out.append((without.name, json.loads((with_ / "summary.json").read_text()),
                        json.loads((without / "summary.json").read_text()), with_, without))
    return out


def same_column(a, b):
    """Whether two runs' columns were the same when the gate opened (contact counts and height)."""
    ba, bb = a["dam_break"]["before_gate"], b["dam_break"]["before_gate"]
    return ba["whole"] == bb["whole"] and a["H0"] == b["H0"]


def paired(values):
    """Mean and standard error of the paired differences (nan for fewer than two)."""
    n = len(values)
    if n == 0:
        return math.nan, math.nan
    m = sum(values) / n
    if n < 2:
        return m, math.nan
    return m, math.sqrt(sum((v - m) ** 2 for v in values) / (n - 1) / n)


def difference_text(diffs, form="{:+.3g}", err="{:.2g}"):
    """The mean paired difference, with its standard error once there are two pairs."""
    m, e = paired(diffs)
    return form.format(m) + (" ± " + err.format(e) if math.isfinite(e) else "")


def paired_table(items, quantities):
    """Markdown rows of (label, read, cell format) over items (seed, a, b): each seed's two values
    and the mean difference b - a; and (label, mean, standard error) per quantity."""
    rows = ["| quantity | " + " | ".join(f"{seed}: with, without" for seed, _, _ in items) +
            " | mean difference (without - with) |", "|---|" + "---|" * (len(items) + 1)]
    stats = []
    for label, read, form in quantities:
        diffs = [read(b) - read(a) for _, a, b in items]
        cells = [f"{form.format(read(a))}, {form.format(read(b))}" for _, a, b in items]
        rows.append(f"| {label} | " + " | ".join(cells) + f" | {difference_text(diffs)} |")
        stats.append((label, *paired(diffs)))
    return rows, stats


def lines(base: Path, figure: Path | None = None):
    found = pairs(base)
    head = [f"**Memory against no memory** (Sec. V B, Fig. 19). L0 = 4 cm (a about 4.6): each seed of `{WITHOUT}` "
            f"settles as the same seed of `{WITH}` and collapses without memory from the gate's opening on "
            "(`dam_break.collapse_tangential = memoryless`): one initial microstructure, two contact laws, as in the "
            "paper's Fig. 19. The paper: without memory the height falls faster, fewer crosses leave the top and the "
            "bottom overpacks while it should stay static."]
    if not found:
        return head + ["", "No pair has finished yet.", ""]
    identical = sum(same_column(w, wo) for _, w, wo, _, _ in found)
    rows, stats = paired_table([(seed, w, wo) for seed, w, wo, _, _ in found],
                               [(label, read, "{:.3g}") for label, read in QUANTITIES])
    verdicts = [f"{label} {m / e:+.1f}" for label, m, e in stats if math.isfinite(e) and e > 0]
    out = head + [""] + rows + ["", f"{identical} of {len(found)} pairs had the same column at the gate's opening (contact "
                         "points by region and H0 equal)."]
    if verdicts:
        out.append("Mean difference in its standard errors: " + "; ".join(verdicts) +
                   f" ({len(found)} pairs: a t of 4.3 is the two-sided 95 % bound for 2 degrees of freedom, 2.6 "
                   "for 5).")
    out += bottom_lines(found) + frame_lines(found) + verdict_lines(found)
    if figure is not None:
        path = plot(found, figure)
        out += ["", f"![centre of mass and mean speed with and without memory]({path.relative_to(base)})"]
    return out + [""]


def bottom_lines(found):
    """The column's bottom quarter (validation.write_bottom_region), with and without memory."""
    regions = [[json.loads((f / "bottom_region.json").read_text()) if (f / "bottom_region.json").exists() else None
                for f in (fw, fwo)] for _, _, _, fw, fwo in found]
    regions = [(seed, a, b) for (seed, *_), (a, b) in zip(found, regions) if a and b]
    if not regions:
        return []
    quantities = [("crosses there at the end / before the gate", lambda r: r["final"] / r["before"], "{:.3f}"),
                  ("median displacement of those that started there (mm)", lambda r: 1000 * r["median_displacement"],
                   "{:.2f}"),
                  ("share of them moved by more than a particle size", lambda r: r["moved_more_than_a_particle"],
                   "{:.3f}")]
    return ["", "The column's bottom quarter (crosses centred at x < L0 and z < H0 / 4 before the gate, where the paper "
            "expects a static region):", ""] + paired_table(regions, quantities)[0]


# Fig. 19's frames, in seconds after the gate's opening (its t = 0). A run that ended before a frame
# (its collapse over: mean speed below 0.1 mm/s) is read at its last record.
FRAMES = [0.15, 0.30, 0.45, 0.60, 0.75, 0.90, 1.05, 3.00]


def centre_height(folder: Path, summary):
    """[(time after the gate's opening, z_cm / z_cm at the opening)] from the gravitational energy
    M g z_cm of energy_series.csv (the floor at z = 0); None without the file."""
    path = folder / "energy_series.csv"
    if not path.exists():
        return None
    with open(path) as f:
        rows = [(float(r["time"]), float(r["gravitational"])) for r in csv.DictReader(f)]
    t_gate = summary["dam_break"]["gate_open_time"]
    at_gate = interpolate(rows, t_gate)
    return [(t - t_gate, e / at_gate) for t, e in rows if t >= t_gate]


def interpolate(rows, t):
    for (t0, e0), (t1, e1) in zip(rows, rows[1:]):
        if t0 <= t <= t1:
            return e0 + (e1 - e0) * (t - t0) / (t1 - t0) if t1 > t0 else e0
    return rows[-1][1] if rows and t > rows[-1][0] else math.nan


def frame_lines(found):
    """The centre of mass's height at Fig. 19's frames, with and without memory, and the paired
    difference."""
    curves = [(centre_height(fw, w), centre_height(fwo, wo)) for _, w, wo, fw, fwo in found]
    curves = [(a, b) for a, b in curves if a and b]
    if not curves:
        return []
    speeds = [(read_speeds(fw, "time", "mean_speed"), read_speeds(fwo, "time", "mean_speed")) for _, _, _, fw, fwo in found]
    out = ["", f"The centre of mass's height z_cm / z_cm(gate) (from the gravitational energy) and the mean speed at the "
           f"paper's frames (Fig. 19; {len(curves)} pairs; a run whose collapse was over before a frame is read at its "
           "end):", "", "| t after the gate (s) | z_cm with memory | without | difference (without - with) | "
           "mean speed with memory (mm/s) | without (mm/s) |", "|---|---|---|---|---|---|"]
    for frame in FRAMES:
        a = [interpolate(with_, frame) for with_, _ in curves]
        b = [interpolate(without, frame) for _, without in curves]
        diff = difference_text([y - x for x, y in zip(a, b)], "{:+.3f}", "{:.3f}")
        va = [1000 * interpolate(w, frame) for w, _ in speeds]
        vb = [1000 * interpolate(wo, frame) for _, wo in speeds]
        out.append(f"| {frame:.2f} | {sum(a) / len(a):.3f} | {sum(b) / len(b):.3f} | {diff} | "
                   f"{sum(va) / len(va):.3g} | {sum(vb) / len(vb):.3g} |")
    ended = [f"{seed}: {w.get('stop_reason')} at {w['dam_break']['collapse_duration']:.2f} s, "
             f"{wo.get('stop_reason')} at {wo['dam_break']['collapse_duration']:.2f} s" for seed, w, wo, _, _ in found]
    return out + ["", "How each pair's runs ended, with and without memory (time after the gate): " + "; ".join(ended) + "."]


def glance(base: Path):
    """One line for the report's summary, or None before any pair has finished."""
    found = pairs(base)
    if not found:
        return None
    return (f"- Memory against no memory (Fig. 19), {len(found)} seed pairs of one settled column at L0 = 4 cm, without memory minus with: " +
            "; ".join(line[2:].rstrip(";.") for line in verdict_lines(found)[2:5]) + ".")


def verdict_lines(found):
    """The paper's four observations of Sec. V B, each beside the paired difference that tests it."""
    def diff(read):
        return difference_text([read(wo, fwo) - read(w, fw) for _, w, wo, fw, fwo in found])

    def early_height(summary, folder):
        curve = centre_height(folder, summary)
        return interpolate(curve, FRAMES[0]) if curve else math.nan

    def bottom(summary, folder):
        path = folder / "bottom_region.json"
        return 1000 * json.loads(path.read_text())["median_displacement"] if path.exists() else math.nan

    capped = sum(wo.get("stop_reason") != "collapse_over" for _, _, wo, _, _ in found)
    capped_with = sum(w.get("stop_reason") != "collapse_over" for _, w, _, _, _ in found)
    return ["", "Against the paper's description, without memory minus with (mean ± standard error over the pairs):",
            f"- the height falls faster: z_cm / z_cm(gate) {FRAMES[0]:.2f} s after the gate {diff(early_height)};",
            f"- the bottom deforms where it should stay static: median displacement of the bottom quarter's crosses "
            f"{diff(bottom)} mm;",
            f"- it overpacks: coordination at the end {diff(lambda s, _: final_coordination(s))}; "
            f"{capped} of {len(found)} columns without memory and {capped_with} with memory still crept at the time "
            "cap (the stop test: mean speed below 0.1 mm/s);",
            f"- fewer crosses leave the top: not measured as such; the runout ratio differs by "
            f"{diff(lambda s, _: s['dam_break']['runout_ratio'])}, each read at its run's end (a column that still "
            "creeps, at the time cap)."]


def read_speeds(folder: Path, x="time_over_tau", y="speed_over_sqrt_gH0"):
    """[(x, y)] of collapse_speeds.csv."""
    with open(folder / "collapse_speeds.csv") as f:
        return [(float(r[x]), float(r[y])) for r in csv.DictReader(f)]


def plot(found, path: Path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (height, speed) = plt.subplots(1, 2, figsize=(11, 4))
    for k, (seed, w, wo, with_, without) in enumerate(found):
        for folder, summary, colour, label in ((with_, w, "k", "with memory"), (without, wo, "tab:red", "without memory")):
            speed.plot(*zip(*read_speeds(folder)), color=colour, lw=1, alpha=0.8, label=label if k == 0 else None)
            curve = centre_height(folder, summary)
            if curve:
                height.plot(*zip(*curve), color=colour, lw=1, alpha=0.8, label=label if k == 0 else None)
    for frame in FRAMES:
        height.axvline(frame, color="0.85", lw=0.8, zorder=0)
    height.set_xlabel("t after the gate's opening (s); grey: Fig. 19's frames")
    height.set_ylabel("z_cm / z_cm(gate)")
    speed.set_xlabel("t / tau, tau = sqrt(H0 / g)")
    speed.set_ylabel("mean speed / sqrt(g H0)")
    speed.set_yscale("log")  # the creep without memory lies three decades below the collapse
    fig.suptitle(f"1000 crosses, L0 = 4 cm: one column per seed ({len(found)}), two contact laws")
    for ax in (height, speed):
        ax.legend()
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return path
