#!/usr/bin/env python3
"""Checks talus.studies.case_pool: every case runs once, in its own process, with its exit status
reported; a cancelled case stops; cases never see the launcher's MPI variables. Run alone (a
LocalPool of two slots) or under `mpirun -n 3` (rank 0 drives, ranks 1 and 2 serve); the same
assertions hold either way, and rank 0 also checks that the cases ran on more than one rank.

usage: test_case_pool.py DIR
"""
import os
import sys
import time

from talus.studies import case_pool

# A case: records which process ran it and whether it saw an MPI variable, then exits `status`.
CASE = r"""
import os, sys, time
out, status, seconds = sys.argv[1], int(sys.argv[2]), float(sys.argv[3])
leaked = sorted(k for k in os.environ if k.startswith(("OMPI_", "PMIX_", "PMI_")))
with open(out + ".tmp", "w") as f:
    f.write("%d %d %s\n" % (os.getppid(), len(leaked), os.environ.get("OMP_NUM_THREADS")))
os.replace(out + ".tmp", out)
time.sleep(seconds)
sys.exit(status)
"""


def main():
    folder = sys.argv[1]
    ranks = case_pool.launched_ranks()
    pool = case_pool.open_pool(2, "case pool test")  # serving ranks stay inside
    os.makedirs(folder, exist_ok=True)
    script = os.path.join(folder, "case.py")
    with open(script, "w") as f:
        f.write(CASE)
    # Case k exits with status k % 3; case "slow" sleeps far longer than the test and is cancelled.
    cases = [("case%d" % k, k % 3, 0.5) for k in range(7)] + [("slow", 0, 600.0)]
    pending, results, started = list(cases), {}, set()
    t0 = time.time()
    while pending or pool.running:
        while pending and pool.free() > 0:
            name, status, seconds = pending.pop(0)
            cmd = [sys.executable, script, os.path.join(folder, name + ".out"), str(status), str(seconds)]
            pool.start(name, cmd, os.path.join(folder, name + ".log"))
            started.add(name)
        if "slow" in started and "slow" in pool.running and len(results) == 7:
            pool.cancel("slow")
            results["slow"] = "cancelled"
            continue
        name, status = pool.wait_any()
        assert name not in results, "case %s reported twice" % name
        results[name] = status
    pool.close()
    elapsed = time.time() - t0

    for name, status, _ in cases[:-1]:
        assert results[name] == status, "case %s: status %s, expected %s" % (name, results[name], status)
    assert results["slow"] == "cancelled"
    assert elapsed < 60, "the cancelled case was waited for (%.0f s)" % elapsed
    parents = set()
    for name, _, _ in cases:
        parent, leaked, threads = open(os.path.join(folder, name + ".out")).read().split()
        assert leaked == "0", "case %s saw %s MPI variables" % (name, leaked)
        assert threads == "1", "case %s: OMP_NUM_THREADS=%s" % (name, threads)
        parents.add(parent)
    if ranks > 1:
        assert len(parents) >= 2, "under %d ranks every case ran in one process (%s)" % (ranks, parents)
    print("case pool: 8 cases on %d rank(s), %d launching processes, %.1f s" % (ranks, len(parents), elapsed))


if __name__ == "__main__":
    main()
