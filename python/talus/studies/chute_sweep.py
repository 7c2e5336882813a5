"""The flow-state map of Weinhart et al. 2012 (Figs. 4, 9, 10): every combination of base
diameter lambda, filling height H and angle theta is run to --end-time with depth profiles
averaged over the last --average time units, `jobs` cases at once on one thread each. Writes
DIR/sweep_runs.csv: flow state, h, u bar, F, mu, K, alpha and bulk volume fraction per case,
the input of `python3 -m talus fit` (chute_fits) and `plot` (plot_chute).

Under mpirun the cases are spread over the ranks (case_pool.py); --slurm FILE writes a
job array of one case per task instead (slurm_array.py).

Usage: python3 -m talus flowmap SCENARIO [--talus BIN] [--lambda 0,0.5,0.6667,0.8333,1,2] [--heights 10,20,30,40]
       [--angles 20,22,24,26,28,30] [--end-time 2000] [--average 100] [--jobs 2] [--out DIR] [--set K=V]
       [--slurm FILE [--slurm-time LIMIT]] [--case-index I]
"""
import os
import sys

from . import chute_runs, engine, slurm_array


def floats(text):
    return [float(x) for x in text.split(",") if x.strip()]


def run(a):
    """`python3 -m talus flowmap`: a as parsed by talus.studies.cli, with the talus executable
    found and the command line (a.argv) for Slurm array tasks."""
    cases = [(l, H, th) for l in floats(a.lambdas) for H in floats(a.heights) for th in floats(a.angles)]
    slurm_array.check_index(a.case_index, len(cases), "flowmap")
    overrides = ["run.end_time=%r" % a.end_time, "chute.coarse_graining.start=%r" % max(0.0, a.end_time - a.average),
                 "chute.flow_state.stop_when_arrested=true", "run.checkpoint_interval=%r" % a.checkpoint_interval,
                 "run.checkpoint_keep=1"] + a.overrides
    if not cases:
        sys.exit("flowmap: no case (empty --lambda, --heights or --angles)")
    if a.continue_from and not os.path.isdir(a.continue_from):
        sys.exit("flowmap: --continue-from %s: no such folder" % a.continue_from)
    engine.check_scenario(a.talus, a.scenario, chute_runs.case_overrides(cases[a.case_index or 0], overrides))
    if a.slurm:
        slurm_array.write_script(a.slurm, len(cases), "talus-flowmap", a.out, slurm_array.task_argv(a.argv, a.talus),
                                 a.slurm_time)
        return
    runner = chute_runs.Runner(a.talus, a.scenario, a.out, a.jobs, overrides, continue_from=a.continue_from,
                               end_time=a.end_time)
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

