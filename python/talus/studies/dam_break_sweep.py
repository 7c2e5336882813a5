"""Runs an ensemble for every point of a grid of scenario values and tabulates them: the flow map
of Huet et al. 2021, Fig. 9 for a dam break, the repose angle against mu_c (Appendix B 2, Fig. 23)
for the hopper. Any scenario key can be swept; all runs of all points share one pool of jobs.

Usage: python3 -m talus sweep FILE --grid key=v1,v2 [--grid key2=...] [--seeds N] [--jobs J] --out DIR
                             [--set k=v] [--talus BIN] [--slurm FILE [--slurm-time LIMIT]] [--case-index I]
Under mpirun the runs are spread over the ranks (case_pool.py); --slurm FILE writes a job
array of one run per task instead (slurm_array.py).
Writes DIR/<point>/seed_<k>/ and DIR/<point>/ensemble.json per point, then DIR/sweep.json and
DIR/sweep.csv (one row per point: grid values, runs, regime fractions, verdict, mean and standard
deviation of the headline measurements)."""
import csv
import itertools
import json
import os
import sys
from pathlib import Path

from . import engine
from .dam_break_ensemble import REGIMES, run_study, seed_jobs, write_atomic, write_ensemble

# Measurements tabulated per point when the summaries have them (mean and std columns).
HEADLINE = ["L0", "H0", "W0", "aspect_ratio", "runout", "final_height", "com_displacement", "coordination_number",
            "dam_break.runout_ratio", "dam_break.runout_ratio_low", "dam_break.runout_ratio_high",
            "dam_break.height_ratio", "dam_break.height_ratio_low", "dam_break.height_ratio_high",
            "dam_break.com_ratio", "dam_break.time_scale", "repose_angle", "repose_angle_left",
            "repose_angle_right", "pile_height", "particles"]


def parse_grid(specs):
    """["a.b=1,2", "c=x"] -> [("a.b", ["1", "2"]), ("c", ["x"])], with file-free checks."""
    grid = []
    for spec in specs:
        key, sep, values = spec.partition("=")
        items = [v.strip() for v in values.split(",") if v.strip()]
        if not sep or not key or not items:
            sys.exit(f"sweep: --grid {spec}: expected key=value1,value2,...")
        grid.append((key.strip(), items))
    return grid


def point_name(assignment):
    """A folder name that says which values the point has: gate_position=0.04_count=400."""
    return "_".join(f"{key.split('.')[-1]}={value}" for key, value in assignment)


def table_row(assignment, record):
    row = {key: value for key, value in assignment}
    row["point"] = point_name(assignment)
    row["runs"] = record["runs"]
    for r in REGIMES:
        if "regime_fractions" in record:
            row[f"{r}_fraction"] = record["regime_fractions"].get(r, 0.0)
    if "verdict" in record:
        row["majority_regime"] = record["majority_regime"]
        row["verdict"] = record["verdict"]
    for key in HEADLINE:
        if key in record["measurements"]:
            row[f"{key}_mean"] = record["measurements"][key]["mean"]
            row[f"{key}_std"] = record["measurements"][key]["std"]
    return row


def run(args) -> None:
    """`python3 -m talus sweep`: args as parsed by talus.studies.cli, with the talus executable
    found and the command line (args.argv) for Slurm array tasks."""
    grid = parse_grid(args.grid)
    out = Path(args.out)
    points = [list(zip([k for k, _ in grid], values)) for values in itertools.product(*[v for _, v in grid])]
    jobs = []
    for assignment in points:
        overrides = args.overrides + [f"{k}={v}" for k, v in assignment]
        jobs += seed_jobs(args.scenario, out / point_name(assignment), args.seeds, args.first_seed, overrides)
    engine.check_scenario(args.talus, args.scenario, jobs[0][2])
    failed = run_study(jobs, args, "sweep", out)
    if failed is None:
        return
    rows = []
    for assignment in points:
        folder = out / point_name(assignment)
        if not any(folder.glob("seed_*/summary.json")):
            print(f"sweep: no finished run at {folder}", file=sys.stderr)
            continue
        record = write_ensemble(folder, {"case": args.scenario, "overrides": args.overrides + [f"{k}={v}" for k, v in assignment]})
        rows.append(table_row(assignment, record))
    if not rows:
        sys.exit("sweep: no point finished")
    columns = list(dict.fromkeys(c for row in rows for c in row))
    sweep = {"case": args.scenario, "grid": {k: v for k, v in grid}, "seeds": args.seeds, "overrides": args.overrides,
             "points": rows, "failed_runs": [str(f) for f in failed]}
    write_atomic(out / "sweep.json", json.dumps(sweep, indent=2) + "\n")
    tmp = out / f"sweep.csv.{os.getpid()}.tmp"
    with open(tmp, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=columns)
        writer.writeheader()
        for row in rows:
            writer.writerow({c: (f"{row[c]:.10g}" if isinstance(row.get(c), float) else row.get(c, "")) for c in columns})
    os.replace(tmp, out / "sweep.csv")
    print(f"{out}/sweep.csv: {len(rows)} points" + (f", {len(failed)} failed runs" if failed else ""))
