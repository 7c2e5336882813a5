#!/usr/bin/env python3
"""The papers' results, regenerated from the cases under validation/ (scripts/validate.sh).

  validation.py run [--jobs N] [--talus BIN] [--runs DIR] [--only FAMILY,...]
      runs the cases still missing (each family a `python3 -m talus sweep`, finished runs reused, an
      interrupted one run again), then copies every finished run's compact results (summary.json
      and the small CSVs, no VTK, no checkpoints) into validation/<paper>/<family>/.
  validation.py run --slurm DIR [--slurm-time LIMIT] [--talus BIN] [--runs DIR] [--only FAMILY,...]
      runs nothing: writes DIR/<paper>_<study>.sbatch, a Slurm job array of each study's runs
      (one run per task; those finished are reused and end at once), and DIR/submit.sh, which
      submits them all. `validation.py compact --runs DIR` then keeps what they finished.
  validation.py compact [--runs DIR]
      the copying alone, for runs finished while their study still runs.
  validation.py report
      validation/REPORT.md, its figures and the machine-readable results
      (validation/weinhart2012/table1.json, validation/huet2021/runout.json) from the committed
      compact results alone.

The runs themselves go to validation/runs/ (not committed) unless --runs says otherwise.
"""
import argparse
import csv
import json
import math
import os
import shutil
import statistics
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import validation_approximations  # noqa: E402
import validation_centre_of_mass  # noqa: E402
import validation_closures  # noqa: E402
import validation_hstop_mle  # noqa: E402
import validation_memory  # noqa: E402
import validation_regimes  # noqa: E402
import validation_resolution  # noqa: E402
import validation_sensitivity  # noqa: E402
import validation_summary  # noqa: E402
import validation_table3  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
VALIDATION = ROOT / "validation"


def study_module(name):
    """talus.studies.<name>; without a built package, the source file itself (chute_fits needs
    only numpy and scipy, channel_runout_fits nothing), so that the report regenerates on a
    checkout that was never built."""
    import importlib
    try:
        return importlib.import_module("talus.studies." + name)
    except ImportError:
        import importlib.util
        spec = importlib.util.spec_from_file_location(name, ROOT / "python" / "talus" / "studies" / (name + ".py"))
        module = importlib.util.module_from_spec(spec)
        sys.modules[spec.name] = module  # a dataclass looks its module up there
        spec.loader.exec_module(module)
        return module


def run_study_command(args, command, *options):
    """`python3 -m talus COMMAND ...` with the package beside args.talus (its build) first on the
    path, and that talus doing the runs."""
    env = dict(os.environ)
    package = Path(args.talus).resolve().parent / "python"
    paths = [str(package)] if (package / "talus").is_dir() else []
    env["PYTHONPATH"] = os.pathsep.join(paths + [p for p in [env.get("PYTHONPATH")] if p])
    cmd = [sys.executable, "-m", "talus", command, *options, "--talus", args.talus]
    print(" ".join(cmd), flush=True)
    subprocess.run(cmd, check=False, env=env)


KEPT_FILES = ["summary.json", "collapse_speeds.csv", "force_pdf.csv", "fabric.csv", "height_profile.csv",
              "energy_series.csv", "bottom_region.json", "fig14_force_network.png"]  # the picture only where `talus plot` drew it: its CSV is megabytes
# The columns of a run's timeseries.csv kept in energy_series.csv: the gravitational energy gives the
# height of the centre of mass through the collapse (validation_memory.py), at a tenth of the size.
ENERGY_COLUMNS = ["time", "gravitational", "kinetic_translational", "kinetic_rotational", "contacts"]


def write_bottom_region(run: Path):
    """run/bottom_region.json: the crosses of the column's bottom quarter (centre at x < L0 and z <
    H0 / 4) before the gate opened and at the end, and how far those that started there moved,
    from the run's two state files (a restored run has neither). With memory that region stays
    static; without, Huet et al. 2021 (Sec. V B) see it deform and overpack."""
    before, final = run / "state_before_gate.json", run / "state_final.json"
    if not (before.exists() and final.exists() and (run / "summary.json").exists()):
        return
    summary = json.loads((run / "summary.json").read_text())
    l0, h0 = summary["L0"], summary["H0"]
    size = summary.get("dam_break", {}).get("particle_size")

    def centres(path):
        return {p[0]: p[7] for p in json.loads(path.read_text())["particles"]}

    def inside(x):
        return x[0] < l0 and x[2] < 0.25 * h0

    start, end = centres(before), centres(final)
    moved = sorted(math.dist(x, end[i]) for i, x in start.items() if inside(x) and i in end)
    record = {"L0": l0, "H0": h0, "before": sum(map(inside, start.values())), "final": sum(map(inside, end.values())),
              "median_displacement": statistics.median(moved) if moved else None,
              "mean_displacement": sum(moved) / len(moved) if moved else None,
              "moved_more_than_a_particle": sum(d > size for d in moved) / len(moved) if moved and size else None}
    (run / "bottom_region.json").write_text(json.dumps(record, indent=1) + "\n")


def write_energy_series(run: Path):
    """run/energy_series.csv from run/timeseries.csv, when the run has one (a restored run has not)."""
    source = run / "timeseries.csv"
    if not source.exists():
        return
    with open(source, newline="") as f, open(run / "energy_series.csv", "w", newline="") as out:
        reader = csv.DictReader(f)
        writer = csv.writer(out)
        writer.writerow(ENERGY_COLUMNS)
        for row in reader:
            writer.writerow([f"{float(row[c]):.7g}" for c in ENERGY_COLUMNS])


class Family:
    """One sweep: a scenario, the values of one key, seeds per value, fixed overrides."""

    def __init__(self, paper, name, scenario, key, values, seeds, sets, particles):
        self.paper, self.name, self.scenario, self.key = paper, name, scenario, key
        self.values, self.seeds, self.sets, self.particles = values, seeds, sets, particles

    def folder(self, base):
        return base / self.paper / self.name


# Huet et al. 2021, Sec. IV B: the small systems (1000 crosses, 3200 spheres), aspect ratios
# a = H0/L0 from about 1 to 8 set by the gate position L0, three realisations each; and one
# aspect ratio without the tangential memory (Sec. V B). The crosses as the paper simulates them
# (Sec. III C): one contact point per pair of convex parts and the gate removed at t = 0 (its
# friction and finite speed only for Figs. 6-7). The `_manifold` families keep Talus' own
# choice, up to four points per part pair and the gate pulled: their columns are less entangled
# (no stable column in 15 runs, where the paper's are intermittent near a = 1-2).
NO_FRAMES = ["run.vtk_interval=0"]
PAPER_MODEL = NO_FRAMES + ["contact.manifold=false", "dam_break.gate=removed"]
# GJK started cold from last step's normal, as these families' runs were made before the warm
# start became the default: the same bits as their committed results.
PAPER_CROSSES = PAPER_MODEL + ["contact.gjk_warm_start=false"]
# Every point computed (contact.manifold_recycle = 0), as these families' runs were made before
# recycled points became the default: the same bits as their committed results.
MANIFOLD_CROSSES = NO_FRAMES + ["contact.manifold=true", "dam_break.gate=pulled", "contact.manifold_recycle=0"]
SPHERE_BOX = ["dam_break.count=3200", "dam_break.box_length=0.6", "dam_break.box_height=0.35",
              "dam_break.domain_height=0.6", "dam_break.fill_growth=1e-6"]
CROSS_GATES = ["0.035", "0.04", "0.05", "0.065", "0.085"]
FAMILIES = [
    Family("huet2021", "crosses", "examples/dam_break_crosses.toml", "dam_break.gate_position",
           CROSS_GATES, 3, PAPER_CROSSES, "crosses"),
    Family("huet2021", "spheres", "examples/dam_break_spheres.toml", "dam_break.gate_position",
           ["0.03", "0.04", "0.05", "0.07", "0.1"], 3, NO_FRAMES + SPHERE_BOX, "spheres"),
    # Sec. V B, Fig. 19: the same settled column collapses without memory. The pour and the
    # settling keep it (the same bits as `crosses` of the same seed), the collapse does not.
    Family("huet2021", "crosses_memoryless", "examples/dam_break_crosses.toml", "dam_break.gate_position",
           ["0.04"], 3, PAPER_CROSSES + ["dam_break.collapse_tangential=memoryless"], "crosses"),
    Family("huet2021", "crosses_manifold", "examples/dam_break_crosses.toml", "dam_break.gate_position",
           CROSS_GATES, 3, MANIFOLD_CROSSES, "crosses"),
    # The gate's share of the difference: the manifold with the gate removed, one run at each of
    # the two widest columns.
    Family("huet2021", "crosses_manifold_gate_removed", "examples/dam_break_crosses.toml", "dam_break.gate_position",
           ["0.065", "0.085"], 1, NO_FRAMES + ["contact.manifold=true", "dam_break.gate=removed",
                                                "contact.manifold_recycle=0"], "crosses"),
    Family("huet2021", "crosses_manifold_memoryless", "examples/dam_break_crosses.toml", "dam_break.gate_position",
           ["0.04"], 3, MANIFOLD_CROSSES + ["contact.tangential=memoryless"], "crosses"),
    # The paper's model with GJK started from last step's simplex (contact.gjk_warm_start, the
    # default): about twice as fast at rest, not the same bits; its observables against those of
    # `crosses`, which decided the default.
    Family("huet2021", "crosses_gjk_warm", "examples/dam_break_crosses.toml", "dam_break.gate_position",
           ["0.065"], 3, PAPER_MODEL + ["contact.gjk_warm_start=true"], "crosses"),
    # Points recycled from their anchors for 10 um of travel (contact.manifold_recycle): about a
    # third faster at rest; its observables against those of `crosses_manifold` decided the default.
    Family("huet2021", "crosses_manifold_recycle", "examples/dam_break_crosses.toml", "dam_break.gate_position",
           ["0.065"], 3, MANIFOLD_CROSSES[:-1] + ["contact.manifold_recycle=1e-5"], "crosses"),
    # Table III's column, as its wall counts and the densities of `crosses` give it
    # (validation_table3.py): L0 = 12 cm, W0 = 9.3 cm, about 15 cm high.
    Family("huet2021", "crosses_table3", "examples/dam_break_crosses.toml", "dam_break.gate_position",
           ["0.12"], 3, PAPER_CROSSES + ["dam_break.width=0.093", "dam_break.count=1200"], "crosses"),
    # Sec. IV C 2, Fig. 17(a): a column longer than five circumscribed diameters (L0 > 13.5 cm),
    # where the walls no longer set the crosses' fabric; 3000 crosses stand about 15 cm high there.
    # GJK warm-started (the default): none of its runs predates the default.
    Family("huet2021", "crosses_wide", "examples/dam_break_crosses.toml", "dam_break.gate_position",
           ["0.15"], 3, PAPER_MODEL + ["dam_break.count=3000"], "crosses"),
    # Sec. IV C, Fig. 14: the column of 12,000 crosses (L0 = 16.7 cm, H0 about 50 cm), one
    # realisation: some 3 hours on two cores, pour and settling a third of it. Run with the
    # manifold and the pulled gate, as the crosses_manifold family.
    Family("huet2021", "crosses_large", "examples/dam_break_crosses_large.toml", "dam_break.gate_position",
           ["0.167"], 1, MANIFOLD_CROSSES + ["dam_break.count=12000", "dam_break.box_length=1.2",
                                      "dam_break.domain_height=1.6"], "crosses"),
    # The same column with recycled points (the default since they matched `crosses_manifold`), for
    # its wall time on two cores (bench/RESULTS.md) and its observables beside the exact column's.
    Family("huet2021", "crosses_large_recycle", "examples/dam_break_crosses_large.toml", "dam_break.gate_position",
           ["0.167"], 1, MANIFOLD_CROSSES[:-1] + ["contact.manifold_recycle=1e-5", "dam_break.count=12000",
                                           "dam_break.box_length=1.2", "dam_break.domain_height=1.6"], "crosses"),
]


class ChuteStudy:
    """A chute study of Weinhart et al. 2012 run by `python3 -m talus hstop` or `flowmap` (which reuse
    finished cases and resume cut-off ones from their checkpoints)."""

    def __init__(self, name, command, options, tables, scenario="examples/chute.toml", job=None, continue_from=None):
        self.paper, self.name, self.command, self.options, self.tables = "weinhart2012", name, command, options, tables
        self.scenario = scenario
        self.job = job or name  # names its Slurm array: two studies may share a folder
        # A shorter study whose finished cases this one goes on from (flowmap --continue-from);
        # a case not finished there runs from the start.
        self.continue_from = continue_from

    def folder(self, base):
        return base / self.paper / self.name


# Weinhart et al. 2012, lambda = 1: the h_stop staircase (Sect. 6) and steady flows over a map of
# H and theta wide enough for the flow rule and the closures (Sects. 7, 9), averaged over the last
# 100 time units as the paper. The map runs to t = 500, not the paper's 2000 (a quarter of some 27
# core-hours); flowmap_long runs two of its cases to t = 2000, and the one whose F drifted most
# within its window (H = 30 at 26 deg), and the report sets the Froude numbers of both lengths
# side by side, which is what licenses the shorter runs. The 28 deg flows still accelerate at
# t = 500, so flowmap_long runs them to t = 2000 too. A long case goes on from the map's final
# state where the runs folder still holds it (a quarter of its cost saved), and the flow rule
# takes the long run of a case where there is one.
CHUTE_STUDIES = [
    ChuteStudy("hstop", "hstop", ["--lambda", "1"], ["hstop_runs.csv", "hstop_intervals.csv"]),
    ChuteStudy("flowmap", "flowmap", ["--lambda", "1", "--heights", "10,20,30,40", "--angles", "22,24,26,28",
                                      "--end-time", "500", "--average", "100"], ["sweep_runs.csv"]),
    ChuteStudy("flowmap_long", "flowmap", ["--lambda", "1", "--heights", "10,20", "--angles", "24",
                                           "--end-time", "2000", "--average", "100"], ["sweep_runs.csv"]),
    ChuteStudy("flowmap_long", "flowmap", ["--lambda", "1", "--heights", "30", "--angles", "26",
                                           "--end-time", "2000", "--average", "100"], [], job="flowmap_long_H30",
               continue_from="flowmap"),
    ChuteStudy("flowmap_long", "flowmap", ["--lambda", "1", "--heights", "20,30", "--angles", "28",
                                           "--end-time", "2000", "--average", "100"], [], job="flowmap_long_28",
               continue_from="flowmap"),
] + validation_sensitivity.studies(ChuteStudy)
CHUTE_CASE_FILES = ["summary.json", "chute_profile.csv", "chute_series.csv"]
# Weinhart et al. 2012, Table 1, lambda = 1, and the agreement issue 26 asks for.
TABLE1 = {"delta1": 17.708, "delta2": 32.780, "A": 3.355, "beta": 0.196, "gamma": 0.040}
TABLE1_BAR = {"delta1": ("deg", 0.5), "delta2": ("deg", 0.5), "A": ("relative", 0.10), "beta": ("relative", 0.10),
              "gamma": None}


def finished(run: Path) -> bool:
    """A run that ended by itself (an interrupted one wrote a summary too, and runs again)."""
    f = run / "summary.json"
    return f.exists() and json.loads(f.read_text()).get("stop_reason") != "interrupted"


def run_folders(family_dir: Path):
    """{(value, seed): run folder} of the sweep's point folders (<key>=<value>/seed_<k>)."""
    out = {}
    for point in sorted(family_dir.glob("*=*")):
        value = point.name.split("=", 1)[1]
        for run in sorted(point.glob("seed_*")):
            if run.name[5:].isdigit():
                out[(value, int(run.name[5:]))] = run
    return out


def slurm_options(args, study_name):
    """The study command's options that write its Slurm array script instead of running it."""
    if not args.slurm:
        return []
    options = ["--slurm", str(Path(args.slurm).resolve() / f"{study_name}.sbatch")]
    return options + (["--slurm-time", args.slurm_time] if args.slurm_time else [])


def run_chute_study(study, args, runs):
    out = study.folder(runs)
    restore_kept_chute(study, out)
    earlier = ["--continue-from", str(runs / study.paper / study.continue_from)] if study.continue_from else []
    run_study_command(args, study.command, str(ROOT / study.scenario), *study.options, *earlier, "--jobs",
                      str(args.jobs), "--out", str(out), *slurm_options(args, f"{study.paper}_{study.job}"))
    if not args.slurm:
        compact_chute(study, out)


def copy_present(names, source: Path, dest: Path):
    """Copies the files of `names` that `source` holds into `dest`."""
    for name in names:
        if (source / name).exists():
            shutil.copyfile(source / name, dest / name)


def restore_kept_chute(study, out: Path):
    """Puts the cases kept under validation/ back into a runs folder that lacks them (a fresh
    checkout): the study reuses a case by its summary.json, so they are not run again."""
    for case in sorted(study.folder(VALIDATION).glob("lambda*_H*_theta*")):
        target = out / case.name
        if not finished(case) or (target / "summary.json").exists():
            continue
        target.mkdir(parents=True, exist_ok=True)
        copy_present(CHUTE_CASE_FILES, case, target)


def compact_chute(study, out: Path):
    """Copies the study's tables and its finished cases' small files into validation/."""
    if not out.exists():
        return
    dest = study.folder(VALIDATION)
    dest.mkdir(parents=True, exist_ok=True)
    for table in study.tables:
        if (out / table).exists():
            shutil.copyfile(out / table, dest / table)
    kept = 0
    for case in sorted(out.glob("lambda*_H*_theta*")):
        if not finished(case):
            continue
        (dest / case.name).mkdir(exist_ok=True)
        copy_present(CHUTE_CASE_FILES, case, dest / case.name)
        kept += 1
    print(f"weinhart2012/{study.name}: {kept} finished cases kept under {dest}")


def write_submit_script(folder: Path):
    """folder/submit.sh: sbatch of every array script written there."""
    scripts = sorted(folder.glob("*.sbatch"))
    lines = ["#!/bin/sh", "# The validation runs as Slurm job arrays (tools/validation.py run --slurm).", "set -e",
             'cd "$(dirname "$0")"'] + [f"sbatch {f.name}" for f in scripts]
    path = folder / "submit.sh"
    path.write_text("\n".join(lines) + "\n")
    path.chmod(0o755)
    print(f"{path}: submits {len(scripts)} job arrays")


def run(args):
    runs = Path(args.runs).resolve()
    if args.slurm:
        Path(args.slurm).mkdir(parents=True, exist_ok=True)
    only = set(args.only.split(",")) if args.only else None
    for study in CHUTE_STUDIES:
        if not only or study.name in only:
            run_chute_study(study, args, runs)
    for fam in FAMILIES:
        if only and fam.name not in only:
            continue
        out = fam.folder(runs)
        restore_kept(fam, out)
        for run_dir in run_folders(out).values():  # interrupted: run again
            if (run_dir / "summary.json").exists() and not finished(run_dir):
                (run_dir / "summary.json").unlink()
        options = [str(ROOT / fam.scenario), "--grid", f"{fam.key}={','.join(fam.values)}", "--seeds", str(fam.seeds),
                   "--jobs", str(args.jobs), "--out", str(out)]
        for s in fam.sets:
            options += ["--set", s]
        run_study_command(args, "sweep", *options, *slurm_options(args, f"{fam.paper}_{fam.name}"))
        if not args.slurm:
            compact(fam, out)
    if args.slurm:
        write_submit_script(Path(args.slurm).resolve())


def restore_kept(fam: Family, runs_dir: Path):
    """Puts the runs kept under validation/ back into a runs folder that lacks them (a fresh
    checkout), so that the sweep, which passes over runs with a summary.json, does not run
    them again."""
    kept = fam.folder(VALIDATION)
    for (value, seed), run_dir in run_folders(kept).items():
        target = runs_dir / run_dir.parent.name / run_dir.name
        if not finished(run_dir) or (target / "summary.json").exists():
            continue
        target.mkdir(parents=True, exist_ok=True)
        copy_present(KEPT_FILES, run_dir, target)


def gate_opened(run: Path) -> bool:
    """A run, finished or cut off, whose column settled and whose gate opened: its state before
    the gate (contacts, fabric, forces) is measured and final."""
    f = run / "summary.json"
    return f.exists() and bool(json.loads(f.read_text()).get("dam_break", {}).get("before_gate", {}).get("static_reached"))


def compact(fam: Family, runs_dir: Path):
    """Copies the small files of the finished runs, and of the cut-off ones past their gate's
    opening (for the state before it), into validation/<paper>/<family>/<point>/seed_<k>/."""
    kept = 0
    for (value, seed), run_dir in run_folders(runs_dir).items():
        if not (finished(run_dir) or gate_opened(run_dir)):
            continue
        dest = fam.folder(VALIDATION) / run_dir.parent.name / run_dir.name
        dest.mkdir(parents=True, exist_ok=True)
        write_energy_series(run_dir)
        write_bottom_region(run_dir)
        copy_present(KEPT_FILES, run_dir, dest)
        kept += 1
    print(f"{fam.paper}/{fam.name}: {kept} runs kept under {fam.folder(VALIDATION)}")


# ---- the report ----

def mean_err(xs):
    """Mean and its standard error (sample standard deviation / sqrt(n)); nan error for n < 2."""
    n = len(xs)
    if n == 0:
        return float("nan"), float("nan")
    m = sum(xs) / n
    if n < 2:
        return m, float("nan")
    sd = math.sqrt(sum((x - m) ** 2 for x in xs) / (n - 1))
    return m, sd / math.sqrt(n)


def channel_fits():
    """The channel experiments of Huet et al. 2021, Fig. 10 (channel_runout_fits.py)."""
    return study_module("channel_runout_fits").CHANNEL_RUNOUT_FITS


def power_fit(points):
    """Least squares of log y = log K + n log a: (K, n, their standard errors), or None."""
    pts = [(math.log(a), math.log(y)) for a, y in points if a > 0 and y > 0]
    if len(pts) < 3:
        return None
    n = len(pts)
    mx = sum(x for x, _ in pts) / n
    my = sum(y for _, y in pts) / n
    sxx = sum((x - mx) ** 2 for x, _ in pts)
    if sxx == 0:
        return None
    slope = sum((x - mx) * (y - my) for x, y in pts) / sxx
    icpt = my - slope * mx
    res = sum((y - icpt - slope * x) ** 2 for x, y in pts) / (n - 2)
    se_slope = math.sqrt(res / sxx)
    se_icpt = math.sqrt(res * (1 / n + mx * mx / sxx))
    return math.exp(icpt), slope, math.exp(icpt) * se_icpt, se_slope


TABLE3_REGIONS = ["whole", "near_gate", "near_gate_top"]  # whole space, half close to the gate, quarter at its top
TABLE3_ROWS = ["coordination_points", "ground_contacts", "side_wall_contacts", "gate_contacts"]


def spheres_against_channel_experiments(cases):
    """Where each sphere point lies against the published channel fits that hold at its a: inside
    their envelope, or how many of its standard errors outside."""
    fits = channel_fits()
    words = []
    for c in sorted((c for c in cases if c["family"] == "spheres"), key=lambda c: c["aspect_ratio"]):
        a, y, err = c["aspect_ratio"], c["runout_ratio"], c["runout_ratio_err"]
        values = {f.source: f.runout_ratio(a) for f in fits}
        held = [v for v in values.values() if v is not None]
        if not held:
            words.append(f"a = {a:.2f}: no fit holds")
            continue
        low, high = min(held), max(held)
        if low <= y <= high and len(held) > 1:
            where = "between the two"
        else:
            nearest = low if abs(y - low) <= abs(y - high) else high
            off = (y - nearest) / err if err and math.isfinite(err) and err > 0 else float("inf")
            source = next(k for k, v in values.items() if v == nearest)
            where = f"{abs(off):.1f} standard errors {'above' if y > nearest else 'below'} {source}"
        words.append(f"a = {a:.2f}: {y:.3g} ({where})")
    if not words:
        return []
    return [f"The spheres against the channel experiments, point by point: {'; '.join(words)}."]


def moving_columns_fits(cases):
    """The power law of the crosses over the aspect ratios where no realisation stood (regime not
    stable or intermittent): a column that stands has a runout near zero whatever its a, which
    a single power law cannot hold (the paper's Fig. 9: intermittent at low a). Per family with a
    standing column: (K, n, K_err, n_err), the aspect ratios left out, and the count fitted."""
    out = {}
    for fam in ("crosses", "crosses_manifold"):
        mine = [c for c in cases if c["family"] == fam]
        moving = [c for c in mine if c["regime"] not in ("stable", "intermittent")]
        if len(moving) == len(mine):
            continue
        fit = power_fit([(c["aspect_ratio"], c["runout_ratio"]) for c in moving])
        if fit:
            out[fam] = (fit, [c["aspect_ratio"] for c in mine if c not in moving], len(moving))
    return out


def moving_columns_fit_lines(cases):
    out = []
    for fam, ((K, n, K_err, n_err), left, count) in moving_columns_fits(cases).items():
        off = abs(n - 1) / n_err if n_err > 0 else float("inf")
        out.append(f"Without the aspect ratios where a realisation stood (a = {', '.join(f'{a:.2f}' for a in left)}), "
                   f"the {fam} give K = {K:.3g} ± {K_err:.2g} and n = {n:.3g} ± {n_err:.2g} ({count} aspect ratios), "
                   f"{off:.1f} standard errors from the paper's n of about 1.")
    return [" ".join(out)] if out else []


def runout_verdict(fits):
    """Huet et al. 2021, Sec. IV B (Fig. 10): for the crosses n 'seems to be approximately equal
    to 1', and their prefactor K is 'slightly lower' than the spheres'. Said of each family of
    crosses fitted (the paper's contact model, and the manifold's)."""
    out = []
    for fam in ("crosses", "crosses_manifold"):
        if fam not in fits:
            continue
        K, n, K_err, n_err = fits[fam]
        off = abs(n - 1) / n_err if n_err > 0 else float("inf")
        out.append(f"The {fam} exponent n = {n:.3g} ± {n_err:.2g} lies {off:.1f} standard errors from the paper's "
                   f"n of about 1 ({'consistent' if off < 2 else 'not consistent'}).")
        if "spheres" in fits:
            ks, _, ks_err, _ = fits["spheres"]
            gap = (ks - K) / math.hypot(K_err, ks_err)
            out.append(f"Its prefactor K = {K:.3g} lies {'below' if K < ks else 'above'} the spheres' {ks:.3g} by "
                       f"{abs(gap):.1f} combined standard errors; the paper finds it slightly lower.")
    return [" ".join(out)] if out else []


def huet_cases(base=VALIDATION):
    """One record per family and point, from the committed summaries under `base`."""
    cases = []
    for fam in FAMILIES:
        if fam.paper != "huet2021":
            continue
        for point in sorted(fam.folder(base).glob("*=*")):
            runs = [json.loads(f.read_text()) for f in sorted(point.glob("seed_*/summary.json")) if finished(f.parent)]
            # Table III needs only the settled column: a run cut off after its gate opened counts there.
            settled = settled_summaries(point, "seed_*/summary.json")
            if not runs:
                if settled:
                    cases.append(table3_record(fam, point, settled))
                continue
            db = [r.get("dam_break", {}) for r in runs]
            regimes = [r.get("regime", "") for r in runs]
            counts = {g: regimes.count(g) for g in sorted(set(regimes))}
            majority = max(counts, key=counts.get)
            collapsed = [g for g in regimes if g != "stable"]
            regime = majority if len(counts) == 1 else ("intermittent" if collapsed and len(collapsed) < len(regimes)
                                                        else majority)
            rec = {"family": fam.name, "particles": fam.particles, "point": point.name, "runs": len(runs),
                   "regime": regime, "regimes": counts}
            for key, values in [("aspect_ratio", [r["aspect_ratio"] for r in runs]),
                                ("runout_ratio", [d["runout_ratio"] for d in db]),
                                ("height_ratio", [d["height_ratio"] for d in db]),
                                ("L0", [r["L0"] for r in runs]), ("H0", [r["H0"] for r in runs])]:
                rec[key], rec[key + "_err"] = mean_err(values)
            rec.update(table3_cells(settled or runs))
            cases.append(rec)
    return cases


def settled_summaries(folder: Path, pattern: str):
    """The summaries matching `pattern` under `folder` of the runs whose gate has opened."""
    return [json.loads(f.read_text()) for f in sorted(folder.glob(pattern)) if gate_opened(f.parent)]


def table3_cells(summaries):
    """Table III: per region and count, the mean and the standard deviation over the realisations,
    and how many realisations they are."""
    before = [s.get("dam_break", {}).get("before_gate", {}) for s in summaries]
    cells = {"table3_runs": len(summaries)}
    for region in TABLE3_REGIONS:
        for key in TABLE3_ROWS:
            values = [b[region][key] for b in before if key in b.get(region, {})]
            m, e = mean_err(values)
            cells[f"{region}.{key}"] = (m, e * math.sqrt(len(values)) if values else e)
    return cells


def table3_record(fam, point, settled):
    """A point none of whose runs has finished: its Table III counts only (runs = 0 keeps it out
    of the runout table, the fits and the figures)."""
    nan = float("nan")
    rec = {"family": fam.name, "particles": fam.particles, "point": point.name, "runs": 0, "regime": "",
           "regimes": {}}
    for key in ("aspect_ratio", "runout_ratio", "height_ratio"):
        rec[key], rec[key + "_err"] = nan, nan
    for key in ("L0", "H0"):
        rec[key], rec[key + "_err"] = mean_err([s[key] for s in settled])
    rec.update(table3_cells(settled))
    return rec


def family_summaries(base=VALIDATION):
    """{family: the summary.json of each finished run} of the dam-break families."""
    return {fam.name: [json.loads(f.read_text()) for f in sorted(fam.folder(base).glob("*=*/seed_*/summary.json"))
                       if finished(f.parent)]
            for fam in FAMILIES if fam.paper == "huet2021"}


def finite(x):
    return x if isinstance(x, (int, float)) and math.isfinite(x) else None


def fmt(m, e, digits=3):
    if m is None or not math.isfinite(m):
        return "-"
    return f"{m:.{digits}g} ± {e:.2g}" if e is not None and math.isfinite(e) else f"{m:.{digits}g}"


def huet_report(lines, figures, base=VALIDATION):
    all_cases = huet_cases(base)
    cases = [c for c in all_cases if c["runs"] > 0]  # Table III also counts the runs still going
    out = base / "huet2021"
    out.mkdir(parents=True, exist_ok=True)
    runout = [{"particles": c["particles"], "family": c["family"], "aspect_ratio": finite(c["aspect_ratio"]),
               "aspect_ratio_err": finite(c["aspect_ratio_err"]), "runout_ratio": finite(c["runout_ratio"]),
               "runout_ratio_err": finite(c["runout_ratio_err"]), "height_ratio": finite(c["height_ratio"]),
               "height_ratio_err": finite(c["height_ratio_err"]), "regime": c["regime"], "runs": c["runs"]}
              for c in cases]
    (out / "runout.json").write_text(json.dumps(runout, indent=1) + "\n")
    lines += ["## Huet et al. 2021: dam-break collapses of the small systems", "",
              "Each row is one gate position L0 with its realisations (mean ± standard error). "
              "Runout ratio (L_inf - L0)/L0 and height ratio H0/H_inf as in Sec. III C. The spheres' "
              "published fits are the two channel experiments of the paper's Fig. 10 and its Sec. I, as "
              "collected by Lagrée, Staron & Popinet 2011, Eq. (3.1): " + "; ".join(
                  f"{f.source} ({f.material}), {f.linear:g} a for a < {f.a_low:g} and {f.power:g} a^(2/3) for "
                  f"a > {f.a_high:g}" for f in channel_fits()) + ". "
              "The family `crosses` is the paper's simulation (Sec. III C): one contact point per pair of convex "
              "parts (crust and GJK, `contact.manifold = false`) and the gate removed at t = 0. The `crosses_manifold` "
              "families give each face or edge contact up to four points (k/n each) and pull the gate at 43 m/s^2 "
              "with its friction, as the paper does for its Figs. 6-7 only; the 12,000-cross column ran so too.", "",
              "| particles | family | L0 (m) | runs | a = H0/L0 | (L_inf - L0)/L0 | " + " ; ".join(f.source for f in channel_fits()) + " | H0/H_inf | regime |",
              "|---|---|---|---|---|---|---|---|---|"]
    for c in cases:
        published = [f.runout_ratio(c["aspect_ratio"]) for f in channel_fits()] if c["particles"] == "spheres" else []
        published = " ; ".join("-" if v is None else fmt(v, None) for v in published)
        lines.append(f"| {c['particles']} | {c['family']} | {c['L0']:.3g} | {c['runs']} | {fmt(c['aspect_ratio'], c['aspect_ratio_err'])} | "
                     f"{fmt(c['runout_ratio'], c['runout_ratio_err'])} | {published} | "
                     f"{fmt(c['height_ratio'], c['height_ratio_err'])} | {c['regime']} {c['regimes']} |")
    lines.append("")
    fits = {}
    for fam in ("spheres", "crosses", "crosses_manifold"):
        pts = [(c["aspect_ratio"], c["runout_ratio"]) for c in cases if c["family"] == fam]
        fit = power_fit(pts)
        if fit:
            fits[fam] = fit
            lines.append(f"Power law (L_inf - L0)/L0 = K a^n over the {fam}: K = {fit[0]:.3g} ± {fit[2]:.2g}, "
                         f"n = {fit[1]:.3g} ± {fit[3]:.2g} ({len(pts)} aspect ratios).")
    lines += runout_verdict(fits) + spheres_against_channel_experiments(cases) + moving_columns_fit_lines(cases)
    runs = family_summaries(base)
    lines += [""] + validation_regimes.lines(runs, {f.name: f.sets for f in FAMILIES})
    lines += validation_approximations.lines(runs)
    lines += validation_memory.lines(base, out / "fig19_memory_speeds.png")
    com_lines, com_fits = validation_centre_of_mass.lines_and_fits(runs)
    if com_lines:
        path = validation_centre_of_mass.plot(runs, com_fits, out / "fig24_centre_of_mass.png")
        lines += com_lines + [f"![centre of mass against a]({path.relative_to(base)})"]
    lines += ["", "Contacts before the gate opens, as the paper's Table III (whole column; the half close to "
              "the gate; the quarter close to the top of the gate): coordination number (contact points per "
              "particle) and contact points on the ground, the side walls and the gate, mean (σ = standard "
              "deviation over the realisations). The paper's intermittent crosses: 8.20 (0.07), 79.3, 169.2, "
              "72.8 over the whole column; which column that is, below.", "",
              "| particles | family | L0 (m) | runs | region | coordination | ground | side walls | gate |",
              "|---|---|---|---|---|---|---|---|---|"]
    for c in all_cases:
        for region in TABLE3_REGIONS:
            cells = []
            for key in TABLE3_ROWS:
                m, sd = c[f"{region}.{key}"]
                cells.append("-" if not math.isfinite(m) else (f"{m:.3g} ({sd:.2g})" if math.isfinite(sd) else f"{m:.3g}"))
            lines.append(f"| {c['particles']} | {c['family']} | {c['L0']:.3g} | {c['table3_runs']} | {region} | "
                         + " | ".join(cells) + " |")
    lines.append("")
    [table3_family] = [f for f in FAMILIES if f.name == validation_table3.FAMILY]
    settled = settled_summaries(table3_family.folder(base), "*=*/seed_*/summary.json")
    lines += validation_table3.lines(runs | {validation_table3.FAMILY: settled})
    if cases:
        figures.append(plot_huet(cases, out))
        lines += [f"![runout and height ratios against a]({figures[-1].relative_to(base)})", ""]
    huet_micro(lines, figures, base)
    return cases, fits


def read_table(path):
    """A CSV of numbers as {column: [values]}."""
    import csv
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in (rows[0] if rows else {})}


def force_tail(folders, ax, colour, label):
    """Fig. 15(b): the mean PDF of F_c/<F_c> before the gate opens over the runs, drawn on `ax`;
    returns each run's largest ratio (the centre of the last logarithmic bin holding a contact:
    those bins reach 20, the linear ones stop at 6)."""
    import numpy as np
    pdfs = [read_table(d / "force_pdf.csv") for d in folders if (d / "force_pdf.csv").exists()]
    largest = []
    for t in pdfs:
        tail = [x for sc, x, y in zip(t["scale"], t["force_ratio"], t["density"]) if sc == 1 and y > 0]
        if tail:
            largest.append(max(tail))
    if pdfs:
        logs = [[(x, y) for sc, x, y in zip(t["scale"], t["force_ratio"], t["density"]) if sc == 1] for t in pdfs]
        xs = [x for x, _ in logs[0]]
        if all(len(l) == len(xs) for l in logs):
            mean = np.mean([[y for _, y in l] for l in logs], axis=0)
            ax.plot(xs, np.where(mean > 0, mean, np.nan), "-", color=colour, label=f"{label} ({len(pdfs)} runs)")
    return largest


def plane_fabric_of(tensors):
    """The fabric of several runs: the anisotropy and preferred direction (degrees from x, in
    [0, 180)) of their mean tensor <n n>, and the direction's jackknife standard error (nan for
    one run). Directions are axial, so they are never averaged as angles: 10 and 170 degrees are
    both near the horizontal, their mean 90 is not."""
    def of(ts):
        xx = sum(t["xx"] for t in ts) / len(ts)
        xz = sum(t["xz"] for t in ts) / len(ts)
        zz = sum(t["zz"] for t in ts) / len(ts)
        two = math.atan2(2 * xz, xx - zz)  # twice the major axis' angle
        return 4 * math.hypot(0.5 * (xx - zz), xz), two
    aniso, two = of(tensors)
    n = len(tensors)
    err = float("nan")
    if n > 1:  # jackknife over the runs, on the doubled angle (wrapped to the nearest turn)
        dev = [math.remainder(of(tensors[:k] + tensors[k + 1:])[1] - two, 2 * math.pi) for k in range(n)]
        mean = sum(dev) / n
        err = 0.5 * math.degrees(math.sqrt((n - 1) / n * sum((d - mean) ** 2 for d in dev)))
    return aniso, math.degrees(two / 2) % 180.0, err


def fabric_rows(folders, summaries):
    """{L0: ([per-run fabric tensor], [per-run aspect ratio], [run folder])} of the runs before
    the gate opens."""
    by_l0 = {}
    for d, summary in zip(folders, summaries):
        f = summary["dam_break"]["before_gate"].get("fabric_xz", {})
        if "xx" in f:
            tensors, ratios, runs = by_l0.setdefault(summary["L0"], ([], [], []))
            tensors.append(f)
            ratios.append(summary["aspect_ratio"])
            runs.append(d)
    return by_l0


def draw_fabric(folders, polar, colour, label):
    """Fig. 17: the mean branch-vector density in the xz plane over the runs, drawn on `polar`."""
    import numpy as np
    tabs = [read_table(d / "fabric.csv") for d in folders if (d / "fabric.csv").exists()]
    if tabs:
        theta = np.array(tabs[0]["theta"])
        mean = np.mean([t["density"] for t in tabs], axis=0)
        polar.plot(np.concatenate([theta, theta + np.pi, theta[:1]]), np.concatenate([mean, mean, mean[:1]]),
                   "-", color=colour, label=label)


def huet_micro(lines, figures, base=VALIDATION):
    """Huet et al. 2021, Figs. 12, 15 and 17 from every kept run of the spheres and the crosses:
    the mean speed against t/tau_c, the PDF of F_c/<F_c> before the gate opens (its tail: the
    largest ratio, 14 for spheres and 32 for crosses in the paper) and the branch-vector fabric
    of each column width."""
    runs = {}
    for fam in ("spheres", "crosses", "crosses_manifold", "crosses_wide", "crosses_large"):
        folder = base / "huet2021" / fam
        runs[fam] = sorted(d for d in folder.glob("*=*/seed_*") if gate_opened(d))
    if not any(runs.values()):
        return
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 3, figsize=(17, 4), gridspec_kw={"width_ratios": [1, 1, 1.3]})
    polar = fig.add_subplot(1, 3, 3, projection="polar")
    axes[2].remove()
    lines += ["Microstructure before the gate opens and collapse speeds, over every kept run (Figs. 12, 15, 17):", "",
              "| family | runs | L0 (m) | largest F_c/<F_c> (log bins, mean of runs) |", "|---|---|---|---|"]
    colours = {"spheres": "tab:blue", "crosses": "k", "crosses_manifold": "tab:purple", "crosses_wide": "tab:green",
               "crosses_large": "tab:orange"}
    columns = []  # (family, L0, aspect ratio, runs, anisotropy, direction, error, circumscribed diameter, folders)
    for fam, folders in runs.items():
        if not folders:
            continue
        largest = force_tail(folders, axes[1], colours[fam], fam)
        for d in folders:  # Fig. 12
            if finished(d) and (d / "collapse_speeds.csv").exists():
                t = read_table(d / "collapse_speeds.csv")
                axes[0].plot(t["time_over_tau"], t["speed_over_sqrt_gH0"], "-", color=colours[fam], lw=0.6, alpha=0.6)
        summaries = [json.loads((d / "summary.json").read_text()) for d in folders]
        l0 = sorted({r["L0"] for r in summaries})
        size = summaries[0]["dam_break"].get("particle_size", float("nan"))
        m_l, e_l = mean_err(largest)
        lines.append(f"| {fam} | {len(folders)} | {l0[0]:.3g}{'' if len(l0) == 1 else f'-{l0[-1]:.3g}'} | {fmt(m_l, e_l)} |")
        for width, (tensors, ratios, kept) in sorted(fabric_rows(folders, summaries).items()):
            columns.append((fam, width, sum(ratios) / len(ratios), len(tensors), *plane_fabric_of(tensors), size, kept))
        if fam == "spheres":
            draw_fabric(folders, polar, colours[fam], "spheres, every column")
    # The crosses' fabric turns with the column's width: one curve per width.
    crosses = [c for c in columns if c[0] != "spheres"]
    cmap = plt.get_cmap("viridis")
    for k, (_fam, width, *_rest, kept) in enumerate(crosses):
        draw_fabric(kept, polar, cmap(k / max(1, len(crosses) - 1)), f"crosses, L0 = {100 * width:.3g} cm")
    axes[0].set(xlabel="t / tau_c", ylabel="mean speed / sqrt(g H0)", title="Fig. 12: every run", xlim=(0, 12))
    axes[1].set(xscale="log", yscale="log", xlabel="F_c / <F_c>", ylabel="PDF", title="Fig. 15(b): before the gate opens")
    axes[1].legend(fontsize=8)
    polar.set_title("Fig. 17: branch vectors, xz plane", fontsize=9)
    polar.legend(fontsize=7, loc="center left", bbox_to_anchor=(1.12, 0.5))
    fig.tight_layout()
    path = base / "huet2021" / "fig12_15_17_speed_forces_fabric.png"
    fig.savefig(path, dpi=110)
    plt.close(fig)
    figures.append(path)
    lines += ["", "The fabric before the gate opens, per column width: the anisotropy and preferred direction of "
              "the runs' mean tensor <n n> of projected branch vectors (xz plane, wall contacts left out as in "
              "the paper), the direction's error by jackknife over the runs. The paper's Fig. 17(a) averages 30 "
              "sphere and 60 cross assemblies whose column is longer than five circumscribed diameters d_c: the "
              "spheres' branch vectors prefer the vertical, the crosses' the horizontal (a cross lies flat). Its "
              "Fig. 17(b) has narrow, tall columns (top-driven and buckling collapses), where the walls stand "
              "the crosses' arms upright and the branch vectors prefer the vertical.", "",
              "| family | L0 (m) | L0 / d_c | a = H0/L0 | runs | anisotropy | preferred direction (deg from x) | | the paper |",
              "|---|---|---|---|---|---|---|---|---|"]
    for fam, width, aspect, n, aniso, direction, err, size, _kept in columns:
        got = leaning(direction, err)
        lines.append(f"| {fam} | {width:.3g} | {width / size:.2g} | {aspect:.2g} | {n} | {aniso:.3g} | "
                     f"{fmt(direction, err)} | {got} | {paper_fabric(fam, width / size, aspect, got)} |")
    if not runs["crosses_wide"]:
        lines += ["", "The wide column (`crosses_wide`, L0 = 15 cm, 5.5 d_c) has not run yet."]
    lines += large_column_lines(runs["crosses_large"], base)
    lines += ["", f"![speeds, force PDF and fabric]({path.relative_to(base)})", ""]


def large_column_lines(folders, base=VALIDATION):
    """Fig. 14: the contacts of the 12,000-cross column before the gate opens, beside the paper's
    count. Its 98,939 contacts give 2 x 98,939 / 12,000 = 16.5 per cross, twice the 8.20 of its
    own Table III for the small columns, while 98,939 / 12,000 = 8.24 agrees with it: the figure
    seems to count each contact from both of its crosses."""
    out = []
    for d in folders:
        summary = json.loads((d / "summary.json").read_text())
        before = summary["dam_break"]["before_gate"]
        whole = before["whole"]
        points = whole["contact_points"] // 2
        out += ["", f"**The column of {whole['particles']:,} crosses** (Fig. 14; L0 = {summary['L0']:.3g} m, "
                f"H0 = {summary['H0']:.3g} m, a = {summary['aspect_ratio']:.2g}, one realisation, settled at "
                f"t = {before['time']:.3g} s): {points:,} contact points between crosses, "
                f"{whole['coordination_points']:.2f} per cross ({whole['coordination']:.2f} touching neighbours), "
                f"and {whole['ground_contacts'] + whole['side_wall_contacts'] + whole['gate_contacts']:,} on the walls. "
                "The paper counts 98,939 contacts and 2 x 98,939 / 12,000 = 16.5 per cross, twice the 8.20 of its own "
                "Table III for the small columns; 98,939 / 12,000 = 8.24 would agree with that table, as if each "
                f"contact were counted from both of its crosses. Talus' {whole['coordination_points']:.2f} lies "
                f"{100 * (whole['coordination_points'] / 8.24 - 1):+.0f} % from 8.24."]
        if not finished(d):
            out += ["", f"Its collapse has run to t = {summary['final_time']:.3g} s ({summary['steps']:,} steps) and "
                    "goes on from its checkpoint."]
        else:
            db = summary["dam_break"]
            out += ["", f"Its collapse ended at t = {summary['final_time']:.3g} s ({summary['steps']:,} steps from the "
                    f"pour, {db['collapse_duration']:.3g} s after the gate opened): (L_inf - L0)/L0 = "
                    f"{db['runout_ratio']:.3g} ({db['runout_ratio_low']:.3g} to {db['runout_ratio_high']:.3g} over the "
                    f"front's definitions) and H0/H_inf = {db['height_ratio']:.3g}, the crosses_large row of the "
                    "runout table."]
        picture = d / "fig14_force_network.png"
        if picture.exists():  # drawn by `talus plot` in the run's folder and kept (KEPT_FILES)
            out += ["", "Its contact network before the gate opens (the paper's Fig. 14b), every contact and the ones "
                    "above five times the mean force:", "",
                    f"![force network of the large column]({picture.relative_to(base)})"]
    return out


def leaning(direction, err):
    """The preferred direction of a fabric in words: within 30 degrees of the vertical or the
    horizontal, or between (the error included: a direction that could be either is undecided)."""
    if direction is None or not math.isfinite(direction):
        return ""
    tilt = abs(direction - 90.0)  # 0: vertical, 90: horizontal
    spread = err if math.isfinite(err) else 0.0
    if spread >= 15:
        return "undecided"
    if tilt + spread < 30:
        return "vertical"
    if tilt - spread > 60:
        return "horizontal"
    return "oblique"


def paper_fabric(family, widths, aspect, got):
    """Where Huet et al.'s Fig. 17 speaks for a column L0 = `widths` circumscribed diameters
    wide of aspect ratio `aspect`, whether Talus' fabric leans the same way: spheres vertical
    (a); crosses horizontal beyond 5 diameters (a) and vertical in the tall narrow columns of
    (b), the top-driven and buckling collapses (a = 6 and 7 in its Figs. 6-7; the widths are not
    given, so a >= 4 and under 5 diameters counts as such here); between those no figure."""
    if family == "spheres":
        want, where = "vertical", "Fig. 17(a)"
    elif widths > 5:
        want, where = "horizontal", "Fig. 17(a)"
    elif aspect >= 4:
        want, where = "vertical", "Fig. 17(b)"
    else:
        return "no figure"
    return f"{'as' if got == want else 'unlike'} {where}: {want}"


def plot_huet(cases, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    style = {"spheres": ("o", "tab:blue"), "crosses": ("s", "k"), "crosses_memoryless": ("^", "tab:red"),
             "crosses_manifold": ("s", "tab:purple"), "crosses_manifold_memoryless": ("^", "tab:pink"),
             "crosses_wide": ("D", "tab:green")}
    for fam, (marker, colour) in style.items():
        cs = [c for c in cases if c["family"] == fam]
        if not cs:
            continue
        a = [c["aspect_ratio"] for c in cs]
        for ax, key in zip(axes, ["runout_ratio", "height_ratio"]):
            ax.errorbar(a, [c[key] for c in cs], yerr=[c[key + "_err"] if math.isfinite(c[key + "_err"]) else 0 for c in cs],
                        fmt=marker, color=colour, label=fam, capsize=3)
    for fit, colour in zip(channel_fits(), ("b", "tab:cyan")):
        for branch, style in (("linear", "--"), ("power", ":")):
            a, y = fit.curve(branch, 10.5)  # past the widest column, a = 9.4
            if a:
                axes[0].plot(a, y, style, color=colour, lw=1, label=fit.label(branch))
    axes[0].set(xscale="log", yscale="log", xlabel="a = H0/L0", ylabel="(L_inf - L0)/L0", title="Huet et al. 2021, Fig. 10")
    axes[1].set(xlabel="a = H0/L0", ylabel="H0/H_inf", title="Huet et al. 2021, Fig. 11")
    for ax in axes:
        ax.legend(fontsize=8)
    fig.tight_layout()
    path = out / "fig10_11_runout_height.png"
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def determined(block):
    """A fit whose every parameter is known to better than half its value: a staircase too short
    for its curve's asymptotes gives parameters at their bounds with errors larger than themselves."""
    return bool(block) and all(math.isfinite(block["se"][k]) and block["se"][k] < 0.5 * abs(v)
                               for k, v in block["params"].items())


def height_groups(heights):
    """The filling heights, sorted, in runs of the staircase's step of 2: [[4, 6, ..., 28], [40]]."""
    groups = []
    for h in sorted(set(heights)):
        if groups and h - groups[-1][-1] <= 2:
            groups[-1].append(h)
        else:
            groups.append([h])
    return groups


def staircase_lines(chute_fits, intervals):
    """Each arrest interval beside the paper's Eq. 35 curve: the angle it gives at the interval's
    h, or the height at the interval's angle, and how far that lies outside the interval."""
    p = TABLE1
    lines = ["| interval | Talus: arrested, flowing | h (d) | Eq. 35 with Table 1 | outside by |", "|---|---|---|---|---|"]
    worst = 0.0
    for r in intervals:
        if r["kind"] == "angle":
            paper = float(chute_fits.theta_stop35(r["h"], p["A"], p["delta1"], p["delta2"]))
            off = max(r["angle_lo"] - paper, paper - r["angle_hi"], 0.0)
            worst = max(worst, off)
            lines.append(f"| H = {r['H']:g} | {r['angle_lo']:g}°, {r['angle_hi']:g}° | {r['h']:.2f} | "
                         f"theta_stop = {paper:.2f}° | {off:.2f}° |")
        else:
            paper = float(chute_fits.hstop35(r["angle_lo"], p["A"], p["delta1"], p["delta2"]))
            off = max(r["h_lo"] - paper, paper - r["h_hi"], 0.0)
            lines.append(f"| theta = {r['angle_lo']:g}° | h = {r['h_lo']:.2f}, {r['h_hi']:.2f} | | "
                         f"h_stop = {paper:.2f} | {off:.2f} d |")
    return lines, worst


def consistency_lines(chute_fits, intervals, hs):
    """Whether the intervals tell Talus' Eq. 35 fit from the paper's: chi^2 of either curve against
    the interval midpoints, each midpoint uncertain as a uniform spread over its interval (sigma =
    width / sqrt(12)). The paper's curve has no parameter fitted to these points, so its chi^2 has
    as many degrees of freedom as points; the fit's has three fewer."""
    import numpy as np
    from scipy.stats import chi2
    ang = [r for r in intervals if r["kind"] == "angle" and r["h"] != ""]
    if not hs or len(ang) < 4:
        return []
    h = np.array([r["h"] for r in ang], float)
    mid = np.array([0.5 * (r["angle_lo"] + r["angle_hi"]) for r in ang])
    sigma = np.array([(r["angle_hi"] - r["angle_lo"]) / math.sqrt(12) for r in ang])
    paper = {k: TABLE1[k] for k in ("A", "delta1", "delta2")}
    terms = ((mid - chute_fits.theta_stop35(h, **paper)) / sigma) ** 2
    c_paper, worst = float(np.sum(terms)), int(np.argmax(terms))
    c_fit = float(np.sum(((mid - chute_fits.theta_stop35(h, **hs["params"])) / sigma) ** 2))
    n = len(ang)
    p_paper = float(chi2.sf(c_paper, n))
    verdict = ("the paper's parameters describe Talus' arrest intervals as well as a curve through them can, so "
               "where Talus' own fit differs from Table 1 the intervals leave the parameters free (heights that "
               "do not reach delta1's asymptote trade A, delta1 and delta2 against each other), not the simulations"
               if p_paper > 0.05 else "the arrest intervals disagree with the paper's curve")
    return ["", f"Against the {n} interval midpoints (each uncertain by its width / sqrt(12) = {sigma.mean():.3f}°), "
            f"Talus' own fit has chi^2 = {c_fit:.1f} for {n - 3} degrees of freedom and the paper's Table 1 curve "
            f"chi^2 = {c_paper:.1f} for {n} (probability of a larger value {p_paper:.2f}; the largest term, "
            f"{terms[worst]:.1f}, from H = {ang[worst]['H']:g}): {verdict}. Neither counts the scatter of one "
            "realisation's arrest near the curve, which widens every interval's true uncertainty."]


def fixed_a_fit(chute_fits, intervals, hs, steady_flows):
    """How far the intervals pin Eq. 35: the free fit's parameter correlations, and delta1 and
    delta2 fitted with A held at Table 1's value (the one parameter that heights short of
    delta1's asymptote trade against the two angles), with the flow rule through that curve.
    None without a free fit or with fewer than 4 angle intervals."""
    import numpy as np
    from scipy.optimize import curve_fit
    ang = [r for r in intervals if r["kind"] == "angle" and r["h"] != ""]
    if not hs or len(ang) < 4:
        return None
    h = np.array([r["h"] for r in ang], float)
    mid = np.array([0.5 * (r["angle_lo"] + r["angle_hi"]) for r in ang])
    names = ("A", "delta1", "delta2")
    _, cov = curve_fit(chute_fits.theta_stop35, h, mid, p0=[hs["params"][k] for k in names], maxfev=20000)
    se = np.sqrt(np.diag(cov))
    corr = cov / np.outer(se, se)
    A = TABLE1["A"]
    q, qcov = curve_fit(lambda x, d1, d2: chute_fits.theta_stop35(x, A, d1, d2), h, mid,
                        p0=[TABLE1["delta1"], TABLE1["delta2"]], maxfev=20000)
    qse = np.sqrt(np.diag(qcov))
    curve = {"A": A, "delta1": float(q[0]), "delta2": float(q[1])}
    sigma = np.array([(r["angle_hi"] - r["angle_lo"]) / math.sqrt(12) for r in ang])
    out = {"corr": {f"{names[a]}-{names[b]}": float(corr[a, b]) for a, b in ((0, 1), (0, 2), (1, 2))},
           "params": curve, "se": {"delta1": float(qse[0]), "delta2": float(qse[1])}, "n": len(ang),
           "chi2": float(np.sum(((mid - chute_fits.theta_stop35(h, **curve)) / sigma) ** 2)), "flow_rule": None}
    if len(steady_flows) >= 3:
        p, pse, _ = chute_fits.fit_flow_rule([r["h"] for r in steady_flows], [r["angle"] for r in steady_flows],
                                             [r["froude"] for r in steady_flows], curve)
        out["flow_rule"] = {"params": p, "se": pse, "n": len(steady_flows)}
    return out


def fixed_a_lines(fixed):
    """The report's paragraph on fixed_a_fit."""
    if not fixed:
        return []
    c, q, e = fixed["corr"], fixed["params"], fixed["se"]
    within = all(abs(q[k] - TABLE1[k]) <= TABLE1_BAR[k][1] for k in ("delta1", "delta2"))
    text = (f"The intervals pin the curve, not its three parameters: the free fit's correlations are A-delta1 "
            f"{c['A-delta1']:.2f}, A-delta2 {c['A-delta2']:.2f} and delta1-delta2 {c['delta1-delta2']:.2f}. With A "
            f"held at Table 1's {q['A']}, the same {fixed['n']} intervals give delta1 = {fmt(q['delta1'], e['delta1'], 4)}° "
            f"and delta2 = {fmt(q['delta2'], e['delta2'], 4)}° (Table 1: {TABLE1['delta1']}°, {TABLE1['delta2']}°; chi^2 "
            f"= {fixed['chi2']:.1f} for {fixed['n'] - 2} degrees of freedom): "
            + ("both angles within the 0.5° bar." if within else "not both within the 0.5° bar."))
    fr = fixed["flow_rule"]
    if fr:
        text += (f" The flow rule through that curve, over the {fr['n']} steady flows: beta = "
                 f"{fmt(fr['params']['beta'], fr['se']['beta'])}, gamma = {fmt(fr['params']['gamma'], fr['se']['gamma'])}.")
    return ["", text]


def wrong_side_lines(chute_fits, staircase):
    """The staircase's cases that land on the other side of the paper's curve: arrested where
    Eq. 35 says the layer flows (theta above theta_stop(h)), or flowing below it; by how far in
    angle. A staircase that stops finding a flowing case has no interval there, so this is where a
    disagreement of the thick layers first shows."""
    p = TABLE1
    wrong = []
    for r in staircase:
        if r["h"] == "":
            continue
        excess = r["angle"] - float(chute_fits.theta_stop35(r["h"], p["A"], p["delta1"], p["delta2"]))
        if (bool(r["arrested"]) and excess > 0) or (not bool(r["arrested"]) and excess < 0):
            wrong.append((r, excess))
    if not wrong:
        return ["Every case lies on the side of the paper's curve that its outcome says.", ""]
    lines = [f"{len(wrong)} of {len(staircase)} cases lie on the other side of the paper's curve:", "",
             "| H | theta | h (d) | outcome | arrest time | theta - theta_stop(h) of Eq. 35 |", "|---|---|---|---|---|---|"]
    for r, excess in wrong:
        t = r.get("arrest_time")
        arrest = f"{t:.0f}" if isinstance(t, float) else ""
        lines.append(f"| {r['H']:g} | {r['angle']:g}° | {r['h']:.2f} | {r['flow_state']} | {arrest} | {excess:+.2f}° |")
    # The paper's own cases at H = 20 (Fig. 3) lie off its fitted curve as well.
    fig3 = [r for r in staircase if r["H"] == 20]
    if fig3:
        outcome = ", ".join(f"{r['angle']:g}° {r['flow_state']}" for r in fig3)
        h20 = fig3[0]["h"]
        stop20 = float(chute_fits.theta_stop35(h20, p["A"], p["delta1"], p["delta2"]))
        lines += ["", f"Weinhart et al.'s Fig. 3 (H = 20, the same base) has the flow stop for theta <= 20.5° and "
                  f"stay steady from 21° on, although Eq. 35 puts theta_stop at {stop20:.2f}° for the h = "
                  f"{h20:.1f} of Talus' H = 20 layer: its own cases lie up to {20.5 - stop20:.2f}° off its fit. "
                  f"Talus at H = 20: {outcome}."]
    thick = [excess for r, excess in wrong if bool(r["arrested"]) and excess > 0.5]
    if thick:
        lines += ["", f"{len(thick)} thick layers arrest more than 0.5° (the bar on delta1 and delta2) above the "
                  "paper's curve: a disagreement beyond the staircase's resolution, growing with h."]
    return lines + [""]


def preparation_lines(chute_fits, out, staircase):
    """The staircase under the paper's literal fill rule (hstop_fill_growth/: the region raised by
    0.01 d per refused placement, which leaves the layer at a volume fraction near 0.15 in a column
    about four times H) beside the present one (chute.initial_volume_fraction = 0.3, the paper's
    stated fraction), case by case where both ran the same (H, theta)."""
    old = chute_fits._read(str(out / "hstop_fill_growth" / "hstop_runs.csv"))
    if not old:
        return []
    p = TABLE1
    thick = [r for r in old if bool(r["arrested"]) and r["h"] != "" and
             r["angle"] - float(chute_fits.theta_stop35(r["h"], p["A"], p["delta1"], p["delta2"])) > 0.5]
    thick_heights = ", ".join("%g" % r["H"] for r in thick)
    top_H = max(r["H"] for r in old)
    lines = [f"**Preparation.** A first staircase ({len(old)} cases, H = 4 to {top_H:g}, kept in "
             "`weinhart2012/hstop_fill_growth/`) placed the layer by the paper's literal rule: the filling region "
             "rises by 0.01 d at each refused placement. That rule leaves a volume fraction near 0.15 at the bottom "
             "and 0.03 at the top of a column about four times H, not the paper's stated 'about 0.3' (Sect. 5): the "
             "bottom of the column lands and settles before the rest arrives, so a thick layer is built on a bed "
             f"already at rest. There {len(thick)} thick layers (H = "
             f"{thick_heights}) arrested more than 0.5° above the paper's curve. The "
             "present staircase places the layer at the stated fraction 0.3 (`chute.initial_volume_fraction`), "
             "uniform up to 1.75 H, so that the whole layer compacts at once.", ""]
    new = {(r["H"], r["angle"]): r for r in staircase}
    for case in sorted((out / "hstop").glob("lambda1_H*_theta*")):  # also cases run beside the staircase
        f = case / "summary.json"
        H, angle = case.name.split("_H")[1].split("_theta")
        if f.exists() and (float(H), float(angle)) not in new:
            sm = json.loads(f.read_text())
            new[(float(H), float(angle))] = {"flow_state": sm.get("flow_state"), "h": sm.get("h")}
    both = [(r, new[(r["H"], r["angle"])]) for r in old if (r["H"], r["angle"]) in new]
    if both:
        lines += ["| H | theta | fill rule 0.01 d per refusal | volume fraction 0.3 |", "|---|---|---|---|"]
        for a, b in both:
            lines.append(f"| {a['H']:g} | {a['angle']:g}° | {a['flow_state']}, h = {a['h']:.2f} | "
                         f"{b['flow_state']}, h = {b['h']:.2f} |")
        lines.append("")
    return lines


def plot_hstop(chute_fits, rows, fits, out, mle=None):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for arrested, style, label in ((1, dict(fmt="o", color="k"), "arrested"),
                                   (0, dict(fmt="o", mfc="none", color="tab:red"), "flowing at t = 500")):
        pts = [(r["angle"], r["h"]) for r in rows if bool(r["arrested"]) == bool(arrested) and r["h"] != ""]
        if pts:
            ax.errorbar(*zip(*pts), label=label, **style)
    theta = np.linspace(19.0, 30.0, 200)
    p = TABLE1
    ax.plot(theta, chute_fits.hstop35(theta, p["A"], p["delta1"], p["delta2"]), "b-", lw=1,
            label="Eq. 35, Weinhart et al. 2012 Table 1")
    for key, f, style in (("hstop35", chute_fits.hstop35, "g--"), ("hstop38", chute_fits.hstop38, "m:")):
        block = fits.get(key)
        if determined(block):
            q = block["params"]
            with np.errstate(invalid="ignore", divide="ignore"):  # below delta1 the curve has no height
                ax.plot(theta, f(theta, q["A"], q["delta1"], q["delta2"]), style, lw=1,
                    label=f"Talus, fit of Eq. {key[-2:]} (cases so far)")
    if mle:
        q = mle["params"]
        with np.errstate(invalid="ignore", divide="ignore"):
            ax.plot(theta, chute_fits.hstop35(theta, q["A"], q["delta1"], q["delta2"]), "-.", color="tab:orange", lw=1,
                    label="Talus, Eq. 35 from every case (maximum likelihood)")
    ax.set(xlabel="theta (deg)", ylabel="h (d)", ylim=(0, 42), xlim=(19, 30),
           title="h_stop, lambda = 1 (Weinhart et al. 2012, Fig. 6)")
    ax.legend(fontsize=8, loc="center right")
    fig.tight_layout()
    path = out / "hstop_lambda1.png"
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def weinhart_report(lines, figures, base=VALIDATION):
    """Table 1 (lambda = 1) from the committed staircase and flow map: the fits of
    talus.studies.chute_fits on the cases' tables, beside the paper's values. While the staircase
    still runs, its arrest intervals come from the cases done so far and the fits are partial."""
    chute_fits = study_module("chute_fits")
    out = base / "weinhart2012"
    hstop_dir = out / "hstop"
    # The table the staircase rewrites as it goes, and its finished cases kept since.
    staircase = validation_closures.kept_rows(chute_fits, hstop_dir, "hstop_runs.csv")
    complete = (hstop_dir / "hstop_intervals.csv").exists()
    intervals = (chute_fits._read(str(hstop_dir / "hstop_intervals.csv")) if complete
                 else chute_fits.arrest_intervals(staircase))
    flowmap = [r for r in validation_closures.kept_rows(chute_fits, out / "flowmap") if r.get("lambda") == 1.0]
    long_runs = [r for r in validation_closures.kept_rows(chute_fits, out / "flowmap_long") if r.get("lambda") == 1.0]
    runs = staircase + flowmap
    flows = validation_closures.steady(validation_closures.with_long_runs(flowmap, long_runs))
    lines += ["## Weinhart et al. 2012: h_stop and the flow rule, lambda = 1", ""]
    if not intervals and not runs:
        lines += ["No chute cases have run yet (`scripts/validate.sh run --only hstop,flowmap`).", ""]
        lines += preparation_lines(chute_fits, out, staircase)
        return {}, {}
    fits = chute_fits.fit_all(intervals, runs, 1.0)
    hs = fits.get("hstop35")
    paper_hstop = {k: TABLE1[k] for k in ("A", "delta1", "delta2")}
    map_lines, flow_rules, map_figure = validation_closures.section(
        chute_fits, flowmap, long_runs, hs["params"] if hs else None, determined(hs), paper_hstop, base, staircase)
    fr = flow_rules["talus"]
    groups = height_groups(r["H"] for r in staircase)
    max_h = groups[0][-1] if groups else 0  # how far the staircase itself has climbed
    table = {"lambda": 1}
    for name, block in (("delta1", hs), ("delta2", hs), ("A", hs), ("beta", fr), ("gamma", fr)):
        usable = determined(hs) and bool(block)
        table[name] = float(block["params"][name]) if usable else None
        table[name + "_err"] = float(block["se"][name]) if usable else None
    # The flow rule against the paper's own h_stop curve: the comparison of beta and gamma alone.
    for name in ("beta", "gamma"):
        b = flow_rules["paper_hstop"]
        table[name + "_with_paper_hstop"] = float(b["params"][name]) if b else None
        table[name + "_with_paper_hstop_err"] = float(b["se"][name]) if b else None
    table["staircase_complete"] = complete
    table["staircase_max_H"] = max_h
    table["flow_map_cases"] = len(flowmap)
    fixed = fixed_a_fit(chute_fits, intervals, hs, flows)
    if fixed:
        for name in ("delta1", "delta2"):
            table[name + "_with_paper_A"] = fixed["params"][name]
            table[name + "_with_paper_A_err"] = fixed["se"][name]
        if fixed["flow_rule"]:
            for name in ("beta", "gamma"):
                table[name + "_with_paper_A"] = float(fixed["flow_rule"]["params"][name])
                table[name + "_with_paper_A_err"] = float(fixed["flow_rule"]["se"][name])
    mle_lines, mle = validation_hstop_mle.lines(chute_fits, staircase, {k: TABLE1[k] for k in validation_hstop_mle.NAMES},
                                                TABLE1_BAR)
    if mle:
        for name in validation_hstop_mle.NAMES:
            table[name + "_mle"] = mle["params"][name]
            table[name + "_mle_err"] = validation_hstop_mle.half_width(mle["interval"][name])
            table[name + "_mle_lo"], table[name + "_mle_hi"] = mle["interval"][name]
        table["sigma_mle"] = mle["sigma"]
        if len(flows) >= 3:  # the flow rule through that curve, as through Talus' own and the paper's
            p, pse, _ = chute_fits.fit_flow_rule([r["h"] for r in flows], [r["angle"] for r in flows],
                                                 [r["froude"] for r in flows], mle["params"])
            for name in ("beta", "gamma"):
                table[name + "_mle"], table[name + "_mle_err"] = float(p[name]), float(pse[name])
    out.mkdir(parents=True, exist_ok=True)
    # Ten significant digits: the fits' last bits follow the BLAS the interpreter loaded, and the
    # committed file should not change with the shell that regenerated it.
    table = {k: float(f"{v:.10g}") if isinstance(v, float) else v for k, v in table.items()}
    (out / "table1.json").write_text(json.dumps(table, indent=1) + "\n")

    state = ("complete" if complete else
             f"still running: {len(staircase)} cases so far, filling heights H = "
             f"{' and '.join(f'{g[0]:g} to {g[-1]:g}' if len(g) > 1 else f'{g[0]:g}' for g in groups)} of the 4 to 40 "
             "searched" + (" (the heights past the first gap were run ahead of the staircase, to bracket its thick "
                           "layers sooner)" if len(groups) > 1 else ""))
    lines += [f"**The h_stop staircase** (Sect. 6: the angle falls by 0.5° while the layer flows, H rises by 2 "
              f"once it arrests, arrest = E_kin/E_ela < 1e-5 within t = 500) is {state}. Each interval lies "
              "between the largest arrested and the smallest flowing case; a case still slowing down at t = 500 "
              "counts as flowing, as the criterion says.", ""]
    table_lines, worst = staircase_lines(chute_fits, intervals)
    lines += table_lines + ["", f"The paper's curve passes within {worst:.2f}° of every angle interval so far "
                            "(the intervals are 0.5° wide).", ""]
    lines += wrong_side_lines(chute_fits, staircase)
    lines += validation_sensitivity.lines(chute_fits, staircase, base)
    lines += preparation_lines(chute_fits, out, staircase)
    lines += ["Fits through the interval midpoints (standard errors from the least-squares covariance):", "",
              "| fit | points | A | delta1 | delta2 | err |", "|---|---|---|---|---|---|"]
    for key, label in (("hstop35", "Eq. 35, angle intervals"), ("hstop38", "Eq. 38, height intervals")):
        block = fits.get(key)
        if not block:
            lines.append(f"| {label} | too few | | | | |")
            continue
        q, e = block["params"], block["se"]
        lines.append(f"| {label} | {block['n']} | {fmt(q['A'], e['A'])} | {fmt(q['delta1'], e['delta1'])} | "
                     f"{fmt(q['delta2'], e['delta2'])} | {block.get('err_deg', block.get('err')):.2g} |")
    lines += consistency_lines(chute_fits, intervals, hs)
    lines += fixed_a_lines(fixed)
    lines += mle_lines
    resolution = ""
    if mle and determined(hs):
        resolution_lines, resolution = validation_resolution.lines(
            study_module("hstop_staircase").Staircase, chute_fits, staircase, TABLE1, TABLE1_BAR, mle["sigma"],
            {validation_resolution.INTERVALS: hs["params"], validation_resolution.LIKELIHOOD: mle["params"]},
            validation_hstop_mle.against_paper(chute_fits, validation_hstop_mle.cases_of(staircase), mle, TABLE1)[1:])
        lines += [""] + resolution_lines
    if not determined(hs):
        top = max((r["h"] for r in intervals if r["kind"] == "angle"), default=0.0)
        lines += ["", f"The Eq. 35 fit is not determined yet: heights up to h = {top:.0f} d do not reach the curve's "
                  "asymptote delta1 (h -> infinity), so A, delta1 and delta2 trade off against each other. "
                  "Table 1 below and table1.json stay empty until the staircase reaches its thick layers."]
    lines += ["", f"![h_stop]({plot_hstop(chute_fits, staircase, fits, out, mle).relative_to(base)})", ""]
    figures.append(out / "hstop_lambda1.png")
    lines += map_lines
    if map_figure:
        lines += [f"![flow rule and closures]({map_figure.relative_to(base)})", ""]
        figures.append(map_figure)
    lines += ["Table 1 (beta and gamma with Talus' own h_stop fit; the last two columns hold A at Table 1's value "
              "and fit every case at once, with beta and gamma through each of those curves; see above):", "",
              "| quantity | Talus | Weinhart et al. 2012, Table 1 | difference | within the bar | Talus, A = 3.355 | "
              "Talus, every case (68 %) |",
              "|---|---|---|---|---|---|---|"]
    for name, paper in TABLE1.items():
        v, e = table[name], table[name + "_err"]
        mle_v = table.get(name + "_mle")
        if mle_v is None:
            mle_text = ""
        elif name + "_mle_lo" in table:
            mle_text = f"{mle_v:.4g} ({table[name + '_mle_lo']:.4g} to {table[name + '_mle_hi']:.4g})"
        else:
            mle_text = fmt(mle_v, table[name + "_mle_err"], 4)
        if v is None:
            lines.append(f"| {name} | not yet fitted | {paper} | | | | {mle_text} |")
            continue
        met = validation_summary.within(v, paper, TABLE1_BAR[name])
        verdict = "(no bar)" if met is None else ("yes" if met else "no")
        held = table.get(name + "_with_paper_A")
        held_text = (f"{fmt(held, table[name + '_with_paper_A_err'], 4)}" if held is not None
                     else ("(held)" if name == "A" and "delta1_with_paper_A" in table else ""))
        lines.append(f"| {name} | {v:.4g} ± {e:.2g} | {paper} | {v - paper:+.3g} | {verdict} | {held_text} | {mle_text} |")
    lines.append("")
    return table, {"resolution": resolution, "closures": validation_closures.closures(chute_fits, flows, paper_hstop)}


def report(_args):
    lines = ["# Validation report", "",
             "Regenerated by `scripts/validate.sh` from the compact results under `validation/`; "
             "`scripts/validate.sh run` runs the cases still missing.", ""]
    figures, weinhart, huet = [], [], []
    table, glance = weinhart_report(weinhart, figures)
    cases, fits = huet_report(huet, figures)
    lines += validation_summary.lines(table, TABLE1, TABLE1_BAR, glance, cases, fits, moving_columns_fits(cases),
                                      channel_fits(), validation_memory.glance(VALIDATION))
    lines += weinhart + huet
    (VALIDATION / "REPORT.md").write_text("\n".join(lines) + "\n")
    print(VALIDATION / "REPORT.md")


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = p.add_subparsers(dest="command", required=True)
    r = sub.add_parser("run")
    r.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    r.add_argument("--talus", default=str(ROOT / "build" / "talus"))
    r.add_argument("--runs", default=str(VALIDATION / "runs"))
    r.add_argument("--only", help="studies, comma-separated (" + ",".join([c.name for c in CHUTE_STUDIES] +
                                                                         [f.name for f in FAMILIES]) + ")")
    r.add_argument("--slurm", metavar="DIR", help="write each study's Slurm job array to DIR instead of running")
    r.add_argument("--slurm-time", metavar="LIMIT", help="#SBATCH --time of each array task, e.g. 12:00:00")
    c = sub.add_parser("compact", help="keep the finished runs' results now (while a study still runs)")
    c.add_argument("--runs", default=str(VALIDATION / "runs"))
    sub.add_parser("report")
    args = p.parse_args()
    if args.command == "compact":
        for study in CHUTE_STUDIES:
            compact_chute(study, study.folder(Path(args.runs).resolve()))
        for fam in FAMILIES:
            compact(fam, fam.folder(Path(args.runs).resolve()))
    elif args.command == "run":
        run(args)
        if args.slurm:
            return  # nothing has run yet
    report(args)


if __name__ == "__main__":
    main()
