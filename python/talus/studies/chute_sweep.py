#!/usr/bin/env python3
"""The flow-state map of Weinhart et al. 2012 (Figs. 4, 9, 10): every combination of base
diameter lambda, filling height H and angle theta is run to --end-time with depth profiles
averaged over the last --average time units, `jobs` cases at once on one thread each. Writes
DIR/sweep_runs.csv: flow state, h, u bar, F, mu, K, alpha and bulk volume fraction per case,
the input of chute_fits.py and plot_chute.py.

Under mpirun the cases are spread over the ranks (tools/case_pool.py); --slurm FILE writes a
job array of one case per task instead (tools/slurm_array.py).

usage: chute_sweep.py SCENARIO --talus BIN [--lambda 0,0.5,0.6667,0.8333,1,2] [--heights 10,20,30,40]
       [--angles 20,22,24,26,28,30] [--end-time 2000] [--average 100] [--jobs 2] [--out DIR] [--set K=V]
       [--slurm FILE [--slurm-time LIMIT]] [--case-index I]
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import chute_runs  # noqa: E402
import slurm_array  # noqa: E402


def floats(text):
    return [float(x) for x in text.split(",") if x.strip()]


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("scenario")
    ap.add_argument("--talus", required=True)
    ap.add_argument("--lambda", dest="lambdas", default="0,0.5,0.6666666666666666,0.8333333333333334,1,2")
    ap.add_argument("--heights", default="10,20,30,40")
    ap.add_argument("--angles", default="20,22,24,26,28,30")
    ap.add_argument("--end-time", type=float, default=2000)
    ap.add_argument("--average", type=float, default=100, help="averaging window T at the end (Sect. 7: 100)")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--out", default="results/sweep")
    ap.add_argument("--checkpoint-interval", type=float, default=50,
                    help="time units between checkpoints of each case, which an interrupted case resumes from")
    ap.add_argument("--set", dest="overrides", action="append", default=[])
    slurm_array.add_options(ap)
    a = ap.parse_args(argv)
    cases = [(l, H, th) for l in floats(a.lambdas) for H in floats(a.heights) for th in floats(a.angles)]
    slurm_array.check_index(a.case_index, len(cases), "flowmap")
    if a.slurm:
        args = slurm_array.without_option(sys.argv[1:] if argv is None else argv, "--slurm")
        slurm_array.write_script(a.slurm, len(cases), "talus-flowmap", a.out, args, a.slurm_time)
        return
    overrides = ["run.end_time=%r" % a.end_time, "chute.coarse_graining.start=%r" % max(0.0, a.end_time - a.average),
                 "chute.flow_state.stop_when_arrested=true", "run.checkpoint_interval=%r" % a.checkpoint_interval,
                 "run.checkpoint_keep=1"] + a.overrides
    runner = chute_runs.Runner(a.talus, a.scenario, a.out, a.jobs, overrides)
    mine = cases if a.case_index is None else [cases[a.case_index]]
    pending = [c for c in mine if runner.cached(c) is None]
    print("sweep: %d cases, %d to run" % (len(mine), len(pending)), flush=True)
    while pending or runner.running:
        while pending and runner.free() > 0:
            runner.start(pending.pop(0))
        if runner.running:
            runner.wait_any()
    runner.close()
    if any(runner.cached(c) is None for c in cases):  # an array task whose siblings still run
        print("sweep: %d of %d cases finished" % (sum(runner.cached(c) is not None for c in cases), len(cases)))
        return
    rows = [chute_runs.row_of(c, runner.cached(c), runner.folder(c)) for c in cases]
    chute_runs.write_rows(os.path.join(a.out, "sweep_runs.csv"), rows)
    print("sweep: %s/sweep_runs.csv" % a.out)


if __name__ == "__main__":
    main()
