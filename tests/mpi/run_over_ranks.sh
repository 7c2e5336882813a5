#!/bin/sh
# `talus run` under mpirun: the settling box (walls, rolling and tangential springs) on one rank
# and on two reaches the same static state; the two-rank run's checkpoint restarts on one rank
# and on four, and both go on alike; restarted on two ranks from a checkpoint written while the
# pile still settles, the run goes on bit for bit, on slabs and on a 2 x 2 grid of ranks. Usage: run_over_ranks.sh TALUS SCENARIO WORKDIR
set -eu
talus=$1 scenario=$2 work=$3
mpirun="mpirun --oversubscribe --allow-run-as-root -x OMP_NUM_THREADS=1"
rm -rf "$work" && mkdir -p "$work" && cd "$work"
"$talus" run "$scenario" --set run.end_time=0.3 --out one --threads 1 --quiet
$mpirun -n 2 "$talus" run "$scenario" --set run.end_time=0.3 --out two --threads 1 --quiet \
  --set run.checkpoint_interval=0.1 --set run.checkpoint_keep=5
first=$(ls two/checkpoints/checkpoint_*.h5 | head -n 1)
$mpirun -n 2 "$talus" run "$scenario" --set run.end_time=0.3 --restart "$first" --out again2 --threads 1 --quiet
"$talus" run "$scenario" --set run.end_time=0.35 --restart two/checkpoints/latest.h5 --out again1 --threads 1 --quiet
$mpirun -n 4 "$talus" run "$scenario" --set run.end_time=0.35 --restart two/checkpoints/latest.h5 --out again4 --threads 1 --quiet
grid="--set run.processors=[2,2,1] --set run.end_time=0.06 --threads 1 --quiet"
$mpirun -n 4 "$talus" run "$scenario" $grid --out grid4 --set run.checkpoint_interval=0.03 --set run.checkpoint_keep=5
$mpirun -n 4 "$talus" run "$scenario" $grid --out grid4again --restart "$(ls grid4/checkpoints/checkpoint_*.h5 | head -n 1)"
/usr/bin/python3 - <<'PY'
import json, sys, glob, os
s = {d: json.load(open(d + "/summary.json")) for d in ["one", "two", "again1", "again4", "again2", "grid4", "grid4again"]}
fail = []
def check(ok, what):
    if not ok:
        fail.append(what)
check(s["two"]["ranks"] == 2 and s["again4"]["ranks"] == 4, "rank counts in summary.json")
check(all(s[d]["particles"] == 750 for d in s), "750 particles everywhere")
check(s["two"]["particles_moved_between_ranks"] > 0, "particles crossed the cut while settling")
# Settling is chaotic, so the two piles differ grain by grain; their static states agree: the
# centre of mass height (gravitational energy) within 0.5 % (measured 0.04 %), at rest.
g1, g2 = s["one"]["energies"]["gravitational"], s["two"]["energies"]["gravitational"]
check(abs(g2 - g1) < 5e-3 * g1, f"static piles differ: {g1} against {g2}")
check(s["two"]["energies"]["max_speed"] < 1e-6, "the two-rank pile is at rest")
# Restarted from one checkpoint, a static pile goes on alike on 1 and on 4 ranks: round-off.
a, b = s["again1"]["energies"], s["again4"]["energies"]
for key in ["gravitational", "elastic_normal", "elastic_tangential"]:
    check(abs(a[key] - b[key]) <= 1e-8 * abs(a[key]), f"{key} after restarts: {a[key]} against {b[key]}")
check(abs(s["again1"]["final_time"] - s["again4"]["final_time"]) < 1e-12, "restarts end at the same time")
# On the same two ranks, from t = 0.1 while the grains still move: every row to the last digit.
rows = {d: open(d + "/timeseries.csv").read().splitlines() for d in ["two", "again2"]}
check(rows["again2"] == rows["two"], "the 2-rank restart on 2 ranks left the 2-rank run: " +
      next((f"{a} against {b}" for a, b in zip(rows["two"], rows["again2"]) if a != b), "rows differ"))
check(s["again2"]["energies"] == s["two"]["energies"], "the 2-rank restart on 2 ranks ends elsewhere")
check(float(rows["two"][11].split(",")[2]) > 1e-6, "the pile is at rest by t = 0.1: a weak test")
# The same on a 2 x 2 grid of ranks, from t = 0.03.
check(s["grid4"]["processors"] == [2, 2, 1] and s["grid4again"]["processors"] == [2, 2, 1], "the grid of ranks in summary.json")
rows = {d: open(d + "/timeseries.csv").read().splitlines() for d in ["grid4", "grid4again"]}
check(rows["grid4again"] == rows["grid4"], "the 2 x 2 restart left the 2 x 2 run: " +
      next((f"{a} against {b}" for a, b in zip(rows["grid4"], rows["grid4again"]) if a != b), "rows differ"))
check(s["grid4"]["particles_moved_between_ranks"] > 0, "particles crossed the cuts of the grid")
check(not glob.glob(os.path.join(os.environ.get("TMPDIR", "/tmp"), "talus-two-rank*")), "rank scratch folders left behind")
if fail:
    print("FAILED:", *fail, sep="\n  ")
    sys.exit(1)
print("settling box over ranks: static states agree; the 2-rank checkpoint restarts on 1 and 4 ranks alike;"
      " restarts on 2 ranks and on a 2 x 2 grid go on bit for bit")
PY
