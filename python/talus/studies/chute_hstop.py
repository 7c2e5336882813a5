"""The h_stop search of Weinhart et al. 2012, Sect. 6, for one or more base roughnesses lambda.

From H = H0 and theta = theta0 the angle rises by 1 deg until the layer flows; from then on the
height rises by 2 if the flow arrested, else the angle falls by 0.5 deg. A case is arrested when
E_kin/E_ela < 1e-5 within 500 time units (run.end_time = 500, stop_when_arrested). Each case runs
on one thread; with --jobs N, N cases run at once: the staircases of several lambdas side by side,
and free slots run the possible next cases of a staircase ahead of its result (the one not
needed is stopped). Writes DIR/hstop_runs.csv (every case) and DIR/hstop_intervals.csv (for each
height the angle interval, for each angle the height interval, where arrested turns to flowing).

Under mpirun the cases are spread over the ranks (case_pool.py); --slurm FILE writes a
job array of one staircase (one lambda) per task instead (slurm_array.py).

Usage: python3 -m talus hstop SCENARIO [--talus BIN] [--lambda 1,0.5] [--jobs 2] [--out DIR] [--h0 4]
       [--theta0 21] [--h-max 40] [--set KEY=VALUE ...] [--slurm FILE [--slurm-time LIMIT]]
       [--case-index I]
"""
import os

from . import chute_fits, chute_runs, engine, slurm_array
from .hstop_staircase import Staircase


def write_intervals(path, rows):
    import csv
    cols = ["lambda", "kind", "H", "h", "angle_lo", "angle_hi", "h_lo", "h_hi"]
    tmp = path + ".tmp"
    with open(tmp, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=cols)
        w.writeheader()
        w.writerows(rows)
    os.replace(tmp, path)


def replay(runner, stairs):
    """The rows of finished staircases, from their cached cases alone; None if one is unfinished."""
    rows = []
    for st in stairs:
        while st.case:
            s = runner.cached(st.case)
            if s is None:
                return None
            rows.append(chute_runs.row_of(st.case, s, runner.folder(st.case)))
            st.advance(chute_runs.is_arrested(s))
    return rows


def run(a):
    """`python3 -m talus hstop`: a as parsed by talus.studies.cli, with the talus executable
    found and the command line (a.argv) for Slurm array tasks."""
    lambdas = [float(x) for x in a.lambdas.split(",")]
    slurm_array.check_index(a.case_index, len(lambdas), "hstop")

    # The arrest test of Sect. 6, and the flow height h from a short average at the end.
    overrides = ["run.end_time=%r" % a.end_time, "chute.flow_state.stop_when_arrested=true",
                 "chute.flow_state.arrest_time=%r" % a.end_time,
                 "chute.coarse_graining.start=%r" % max(0.0, a.end_time - 20), "chute.coarse_graining.interval=0.1",
                 "chute.coarse_graining.extra_widths=[]", "run.checkpoint_interval=%r" % a.checkpoint_interval,
                 "run.checkpoint_keep=1"] + a.overrides
    first = (lambdas[0] if a.case_index is None else lambdas[a.case_index], a.h0, a.theta0)
    engine.check_scenario(a.talus, a.scenario, chute_runs.case_overrides(first, overrides))
    if a.slurm:
        slurm_array.write_script(a.slurm, len(lambdas), "talus-hstop", a.out, slurm_array.task_argv(a.argv, a.talus),
                                 a.slurm_time)
        return
    runner = chute_runs.Runner(a.talus, a.scenario, a.out, a.jobs, overrides)

    def staircases(chosen):
        return [Staircase(lam, a.h0, a.theta0, a.h_max, a.theta_min, a.max_cases) for lam in chosen]

    stairs = staircases(lambdas if a.case_index is None else [lambdas[a.case_index]])
    rows = []

    def record(case):
        s = runner.done[case]
        rows.append(chute_runs.row_of(case, s, runner.folder(case)))
        if a.case_index is None:  # an array task writes the table only once every staircase is done
            chute_runs.write_rows(os.path.join(a.out, "hstop_runs.csv"), rows)

    recorded = set()
    while any(st.case for st in stairs):
        # Advance every staircase whose case is known.
        progressed = True
        while progressed:
            progressed = False
            for st in stairs:
                if st.case and runner.cached(st.case) is not None:
                    if st.case not in recorded:
                        record(st.case)
                        recorded.add(st.case)
                    st.advance(chute_runs.is_arrested(runner.done[st.case]))
                    progressed = True
        active = [st for st in stairs if st.case]
        if not active:
            break
        needed = [st.case for st in active]
        useful = set(needed)
        for st in active:
            useful.update(st.successors())
        for case in list(runner.running):
            if case not in useful:
                runner.cancel(case)
        for case in needed:
            if runner.free() > 0:
                runner.start(case)
        for st in active:  # speculate: the flowing branch first (the staircase's usual step)
            for case in reversed(st.successors()):
                if runner.free() > 0 and runner.cached(case) is None:
                    runner.start(case)
        if runner.running:
            runner.wait_any()
    runner.close()  # speculative cases still running are not needed
    if a.case_index is not None:  # a Slurm array task: the tables need every staircase
        rows = replay(runner, staircases(lambdas))
        if rows is None:
            print("h_stop search: lambda %g done; other staircases still run" % lambdas[a.case_index])
            return
        chute_runs.write_rows(os.path.join(a.out, "hstop_runs.csv"), rows)
    write_intervals(os.path.join(a.out, "hstop_intervals.csv"), chute_fits.arrest_intervals(rows))
    print("h_stop search: %d cases; %s/hstop_runs.csv, %s/hstop_intervals.csv" % (len(rows), a.out, a.out))

