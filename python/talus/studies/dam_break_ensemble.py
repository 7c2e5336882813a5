"""Runs one scenario for N seeds and aggregates the summaries: DIR/seed_<k>/ -> DIR/ensemble.json,
DIR/ensemble.csv (one row per measurement) and DIR/runs.csv (one row per run).

Usage: python3 -m talus ensemble FILE --seeds N [--first-seed S] [--jobs J] --out DIR [--set k=v ...]
                                [--talus BIN] [--slurm FILE [--slurm-time LIMIT]] [--case-index I]
       python3 -m talus aggregate DIR      (aggregate the seed_* folders already in DIR)

Huet et al. 2021 repeat every case with different initial microstructures (Sec. IV A, Fig. 9:
three to five runs per case) to tell repeatable cases from intermittent ones. The verdict rule:
with at least two runs, a case is "intermittent" when some runs end stable (regime == "stable")
and others do not (0 < stable runs < runs), "repeatable" otherwise; one run is "undetermined".
"""
import json
import math
import os
import sys
from pathlib import Path

from . import case_pool, engine, slurm_array

VERDICT_RULE = ("runs >= 2: intermittent if 0 < stable runs < runs (Huet et al. 2021, Fig. 9), "
                "repeatable otherwise; runs < 2: undetermined")
REGIMES = ("stable", "fractured", "collapsed")


def write_atomic(path: Path, text: str) -> None:
    """Writes to a temporary name and renames, so a reader never sees half a file."""
    tmp = path.with_name(f"{path.name}.{os.getpid()}.tmp")  # several writers (Slurm array tasks) may finish at once
    tmp.write_text(text)
    os.replace(tmp, path)


def flatten(value, prefix=""):
    """Numeric leaves of a summary as {"dam_break.before_gate.whole.x": 1.0}; booleans count as
    0/1 (their mean is the fraction of runs where they hold); strings and lists are left out."""
    out = {}
    if isinstance(value, dict):
        for key, item in value.items():
            out.update(flatten(item, f"{prefix}.{key}" if prefix else str(key)))
    elif isinstance(value, bool):
        out[prefix] = 1.0 if value else 0.0
    elif isinstance(value, (int, float)) and math.isfinite(value):
        out[prefix] = float(value)
    return out


def statistics(values):
    """n, mean, sample standard deviation (n - 1 in the denominator; 0 for one run), min, max."""
    n = len(values)
    mean = sum(values) / n
    std = math.sqrt(sum((v - mean) ** 2 for v in values) / (n - 1)) if n > 1 else 0.0
    return {"n": n, "mean": mean, "std": std, "min": min(values), "max": max(values)}


def verdict(stable_runs: int, runs: int) -> str:
    if runs < 2:
        return "undetermined"
    return "intermittent" if 0 < stable_runs < runs else "repeatable"


def aggregate(summaries: dict) -> dict:
    """{seed: summary} -> the ensemble record (measurement statistics, regimes, verdict)."""
    flat = {seed: flatten(s) for seed, s in summaries.items()}
    keys = sorted({k for f in flat.values() for k in f})
    measurements = {k: statistics([f[k] for f in flat.values() if k in f]) for k in keys}
    regimes = {seed: s.get("regime") for seed, s in summaries.items() if isinstance(s.get("regime"), str)}
    counts = {r: sum(1 for v in regimes.values() if v == r) for r in REGIMES}
    for v in regimes.values():
        counts.setdefault(v, sum(1 for w in regimes.values() if w == v))
    record = {"runs": len(summaries), "seeds": sorted(summaries), "measurements": measurements}
    if regimes:
        n = len(regimes)
        record["regime_counts"] = counts
        record["regime_fractions"] = {r: c / n for r, c in counts.items()}
        record["stable_fraction"] = counts["stable"] / n
        record["verdict"] = verdict(counts["stable"], n)
        record["verdict_rule"] = VERDICT_RULE
        record["majority_regime"] = max(REGIMES, key=lambda r: (counts[r], -REGIMES.index(r)))
    return record


RUN_COLUMNS = ["L0", "H0", "aspect_ratio", "runout", "final_height", "dam_break.runout_ratio",
               "dam_break.runout_ratio_low", "dam_break.runout_ratio_high", "dam_break.height_ratio",
               "dam_break.height_ratio_low", "dam_break.height_ratio_high", "dam_break.com_ratio",
               "dam_break.time_scale", "dam_break.gate_open_time", "coordination_number", "repose_angle",
               "repose_angle_left", "repose_angle_right", "wall_seconds"]


def blown_up(run: Path) -> bool:
    """A run the blow-up guard stopped (exit status 3): its summary measures no collapse."""
    return json.loads((run / "summary.json").read_text()).get("stop_reason") == "blow_up"


def finished(run: Path) -> bool:
    """A run that ended by itself. One cut off (Ctrl-C, a time limit) wrote a summary too, of a
    collapse not yet over: it is not finished, and goes on from its checkpoint."""
    f = run / "summary.json"
    return f.exists() and json.loads(f.read_text()).get("stop_reason") != "interrupted"


# Simulated seconds between a run's checkpoints: a few minutes of wall time for the small systems,
# so that a run killed outright (a lost machine, the end of a batch job) loses no more.
CHECKPOINT_INTERVAL = 0.05


def run_command(talus: str, scenario: Path, out: Path, overrides) -> list:
    """The command that runs a case, or resumes it from its newest checkpoint, bit for bit, when an
    earlier run of it was cut off."""
    if (out / "checkpoints" / "latest.h5").exists():
        return [talus, "resume", str(out), "--threads", "1", "--quiet"]
    cmd = [talus, "run", str(scenario), "--out", str(out), "--threads", "1", "--quiet", "--overwrite",
           "--checkpoint-interval", repr(CHECKPOINT_INTERVAL)]
    for o in overrides:
        cmd += ["--set", o]
    return cmd


def seed_folders(folder: Path, blown=False):
    """{seed: path} of the finished runs in `folder`, without the runs that blew up; with
    blown=True, only those."""
    runs = {}
    for d in folder.glob("seed_*"):
        if finished(d) and d.name[5:].isdigit() and blown_up(d) == blown:
            runs[int(d.name[5:])] = d
    return dict(sorted(runs.items()))


def write_ensemble(folder: Path, meta: dict | None = None) -> dict:
    runs = seed_folders(folder)
    if not runs:
        sys.exit(f"ensemble: no seed_*/summary.json in {folder}")
    summaries = {seed: json.loads((d / "summary.json").read_text()) for seed, d in runs.items()}
    record = dict(meta or {})
    old = folder / "ensemble.json"
    if not meta and old.exists():  # keep what the run command recorded (case, overrides)
        record.update({k: v for k, v in json.loads(old.read_text()).items() if k in ("case", "overrides")})
    record.update(aggregate(summaries))
    failed = seed_folders(folder, blown=True)
    if failed:
        record["blown_up_seeds"] = sorted(failed)
        print(f"ensemble: left out seeds {sorted(failed)}: their runs blew up (see their summary.json)", file=sys.stderr)
    write_atomic(folder / "ensemble.json", json.dumps(record, indent=2) + "\n")
    lines = ["measurement,n,mean,std,min,max"]
    for key, s in record["measurements"].items():
        lines.append(f"{key},{s['n']},{s['mean']:.10g},{s['std']:.10g},{s['min']:.10g},{s['max']:.10g}")
    write_atomic(folder / "ensemble.csv", "\n".join(lines) + "\n")
    columns = [c for c in RUN_COLUMNS if c in record["measurements"]]
    rows = ["seed,regime," + ",".join(columns)]
    for seed, s in summaries.items():
        f = flatten(s)
        rows.append(f"{seed},{s.get('regime', '')}," + ",".join(f"{f[c]:.10g}" if c in f else "" for c in columns))
    write_atomic(folder / "runs.csv", "\n".join(rows) + "\n")
    return record


def run_all(jobs_list, jobs: int, talus: str) -> list:
    """Runs every (scenario, out, overrides) through a case pool (case_pool.py: `jobs` at
    a time here, one per rank under mpirun), one thread each; returns the failed ones. Finished
    runs are not run again, and cut-off ones resume."""
    pool = case_pool.open_pool(jobs, "ensemble")
    pending = [j for j in jobs_list if not finished(j[1])]
    failed, done, running = [], len(jobs_list) - len(pending), 0
    total = len(jobs_list)
    while pending or running:
        while pending and pool.free() > 0:
            scenario, out, overrides = pending.pop(0)
            out.parent.mkdir(parents=True, exist_ok=True)
            pool.start(out, run_command(talus, scenario, out, overrides), str(out.parent / f"{out.name}.log"))
            running += 1
        out, code = pool.wait_any()
        running -= 1
        done += 1
        status = "ok" if code == 0 else f"failed ({code}), see {out}.log"
        if code != 0:
            failed.append(out)
        print(f"[{done}/{total}] {out}: {status}", flush=True)
    pool.close()
    return failed


def all_finished(jobs_list) -> bool:
    return all(finished(j[1]) for j in jobs_list)


def run_study(jobs_list, args, name: str, out: Path):
    """The runs of a study as its options ask: all of them (`--jobs` at a time, or over MPI
    ranks), only run --case-index (a Slurm array task), or none but the array script (--slurm).
    Returns the failed runs once every run is finished; None while the tables must wait (an
    array written, or an array task whose siblings still run), after exiting 1 if this one failed."""
    slurm_array.check_index(args.case_index, len(jobs_list), name)
    if args.slurm:
        slurm_array.write_script(args.slurm, len(jobs_list), "talus-" + name, out,
                                 slurm_array.task_argv(args.argv, args.talus), args.slurm_time)
        return None
    failed = run_all(jobs_list if args.case_index is None else [jobs_list[args.case_index]], args.jobs, args.talus)
    if not all_finished(jobs_list):
        print(f"{name}: {sum(finished(j[1]) for j in jobs_list)} of {len(jobs_list)} runs finished")
        if failed:
            sys.exit(1)
        return None
    return failed


def seed_jobs(scenario: str, out: Path, seeds: int, first_seed: int, overrides: list):
    return [(Path(scenario), out / f"seed_{k}", overrides + [f"run.seed={k}"])
            for k in range(first_seed, first_seed + seeds)]


def run(args) -> None:
    """`python3 -m talus ensemble`: args as parsed by talus.studies.cli, with the talus
    executable found and the command line (args.argv) for Slurm array tasks."""
    out = Path(args.out)
    jobs = seed_jobs(args.scenario, out, args.seeds, args.first_seed, args.overrides)
    engine.check_scenario(args.talus, args.scenario, jobs[0][2])
    failed = run_study(jobs, args, "ensemble", out)
    if failed is None:
        return
    record = write_ensemble(out, {"case": args.scenario, "overrides": args.overrides})
    if failed:
        print(f"ensemble: {len(failed)} run(s) failed: {', '.join(map(str, failed))}", file=sys.stderr)
    report(out, record)


def aggregate_folder(folder) -> None:
    """`python3 -m talus aggregate DIR`: the tables of the seed_* folders already in DIR."""
    report(folder, write_ensemble(Path(folder)))


def report(folder, record) -> None:
    line = f"{record['runs']} runs"
    if "verdict" in record:
        line += f", stable fraction {record['stable_fraction']:.2f}, {record['verdict']}"
    print(f"{folder}/ensemble.json: {line}")
