"""Runs chute cases with `talus run` (one OpenMP thread each, `jobs` at a time) and reads their
summary.json: the engine of the h_stop search and the flow-state sweep (Weinhart et al. 2012,
Sects. 6 and 8). A case is (lambda, H, theta); its results folder is reused when it already
holds a summary, and a case that was cut off goes on from its newest checkpoint (the studies set
run.checkpoint_interval), so an interrupted search resumes where it stopped."""
import csv
import json
import os
import time

from . import case_pool

COLUMNS = ["lambda", "H", "angle", "flow_state", "arrested", "stop_reason", "final_time", "h", "base", "surface",
           "mean_velocity", "froude", "mu_macro", "K", "alpha", "volume_fraction", "bulk_volume_fraction",
           "arrest_time", "wall_time", "dir"]


def case_name(lam, H, angle):
    return "lambda%g_H%g_theta%g" % (lam, H, angle)


def case_overrides(case, overrides):
    """The scenario values of a case (lambda, H, theta), then the study's own."""
    lam, H, angle = case
    return ["chute.base_diameter=%r" % float(lam), "chute.fill_height=%r" % float(H),
            "chute.angle=%r" % float(angle)] + list(overrides)


def is_arrested(summary):
    return summary.get("stop_reason") == "arrested" or summary.get("flow_state") == "arrested"


def row_of(case, summary, folder):
    lam, H, angle = case
    chute = summary.get("chute", {})
    row = {"lambda": lam, "H": H, "angle": angle, "flow_state": summary.get("flow_state"),
           "arrested": int(is_arrested(summary)), "stop_reason": summary.get("stop_reason"),
           "final_time": summary.get("final_time"), "arrest_time": chute.get("arrest_time"),
           "wall_time": summary.get("wall_time"), "dir": folder}
    for k in ["h", "base", "surface", "mean_velocity", "froude", "mu_macro", "K", "alpha", "volume_fraction",
              "bulk_volume_fraction"]:
        row[k] = summary.get(k)
    return row


class Runner:
    """Starts `talus run` processes through a case pool (case_pool.py: `jobs` at once here,
    or one per rank under mpirun) and reports finished cases."""

    def __init__(self, talus, scenario, out, jobs, overrides, quiet=False, continue_from=None, end_time=None):
        self.talus, self.scenario, self.out = talus, scenario, out
        self.overrides, self.quiet = list(overrides), quiet
        self.continue_from, self.end_time = continue_from, end_time
        self.pool = case_pool.open_pool(jobs, "chute study")
        self.started = {}  # case -> start time
        self.done = {}     # case -> summary
        os.makedirs(out, exist_ok=True)

    @property
    def running(self):
        return self.started

    def folder(self, case):
        return os.path.join(self.out, case_name(*case))

    def cached(self, case):
        path = os.path.join(self.folder(case), "summary.json")
        if case not in self.done and os.path.exists(path):
            with open(path) as f:
                s = json.load(f)
            # An interrupted run goes on; a blown-up one (exit status 3) is run again, so that it
            # fails loudly instead of entering the results as a flow state.
            if s.get("stop_reason") not in ("interrupted", "blow_up"):
                self.done[case] = s
        return self.done.get(case)

    def free(self):
        return self.pool.free()

    def command(self, case):
        # A case cut off (Ctrl-C, a time limit, a lost machine) goes on from its newest checkpoint,
        # bit for bit, instead of starting again: long flows span several runs of a study or array tasks.
        if os.path.exists(os.path.join(self.folder(case), "checkpoints", "latest.h5")):
            return [self.talus, "resume", self.folder(case), "--quiet", "--threads", "1"]
        cmd = [self.talus, "run", self.scenario, "--out", self.folder(case), "--overwrite", "--quiet", "--threads", "1"]
        earlier = self.earlier_end(case)
        if earlier:
            cmd += ["--restart", earlier]
        for o in case_overrides(case, self.overrides):
            cmd += ["--set", o]
        return cmd

    def earlier_end(self, case):
        """The final checkpoint of the case in the earlier sweep (continue_from) when that run went
        to its end time before this one's: the run goes on from there with this sweep's scenario
        (its later averaging window included), which gives the bits of a run from the start."""
        if not self.continue_from:
            return None
        folder = os.path.join(self.continue_from, case_name(*case))
        checkpoint = os.path.join(folder, "checkpoints", "latest.h5")
        try:
            with open(os.path.join(folder, "summary.json")) as f:
                s = json.load(f)
        except FileNotFoundError:
            return None
        ended = s.get("stop_reason") == "end_time" and os.path.exists(checkpoint)
        return os.path.realpath(checkpoint) if ended and s.get("final_time", 0) < self.end_time else None

    def start(self, case):
        if case in self.started or self.cached(case) is not None:
            return
        self.pool.start(case, self.command(case), self.folder(case) + ".log")
        self.started[case] = time.time()
        if not self.quiet:
            print("start  %s" % case_name(*case), flush=True)

    def cancel(self, case):
        self.pool.cancel(case)
        del self.started[case]
        if not self.quiet:
            print("cancel %s (speculative, not needed)" % case_name(*case), flush=True)

    def wait_any(self):
        """Blocks until some running case ends; returns it (its summary is in self.done)."""
        case, status = self.pool.wait_any()
        t0 = self.started.pop(case)
        if status != 0:
            raise RuntimeError("talus run failed for %s (see %s.log)" % (case_name(*case), self.folder(case)))
        s = self.cached(case)
        if s is None:
            raise RuntimeError("talus run left no summary for %s (see %s.log)" % (case_name(*case), self.folder(case)))
        if not self.quiet:
            print("done   %s: %s, h = %s (%.0f s)" % (case_name(*case), s.get("flow_state"), s.get("h"),
                                                     time.time() - t0), flush=True)
        return case

    def close(self):
        self.pool.close()


def write_rows(path, rows):
    tmp = "%s.%d.tmp" % (path, os.getpid())  # several writers (Slurm array tasks) may finish at once
    with open(tmp, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=COLUMNS)
        w.writeheader()
        for r in rows:
            w.writerow({k: ("" if r.get(k) is None else r.get(k)) for k in COLUMNS})
    os.replace(tmp, path)


def read_rows(path):
    rows = []
    with open(path) as f:
        for r in csv.DictReader(f):
            for k in COLUMNS:
                if k in ("flow_state", "stop_reason", "dir"):
                    continue
                r[k] = float(r[k]) if r.get(k) not in (None, "") else None
            rows.append(r)
    return rows
