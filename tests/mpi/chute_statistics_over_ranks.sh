#!/bin/sh
# A steady chute flow on 1, 2 and 4 ranks has the same statistics: the depth-averaged velocity,
# volume fraction and flow height over the averaging window agree within their standard errors.
# A chute flow is chaotic, so runs on different rank counts differ grain by grain, and a shallow
# flow drifts between faster and slower states over tens of sqrt(d/g): one run's own blocks
# underestimate its error. Each rank count therefore runs an ensemble of four seeds, and the
# ensembles' scatter gives the standard errors.
# Usage: chute_statistics_over_ranks.sh TALUS SCENARIO WORKDIR
set -eu
talus=$1 scenario=$2 work=$3
export OMP_NUM_THREADS=1 OMP_WAIT_POLICY=PASSIVE
mpirun="mpirun --oversubscribe --allow-run-as-root -x OMP_NUM_THREADS=1 -x OMP_WAIT_POLICY=PASSIVE"
rm -rf "$work" && mkdir -p "$work" && cd "$work"
# A 10 x 5 base, H = 6 at 26 degrees, which flows steadily after about 20 sqrt(d/g). The contacts
# are 100 times softer than the paper's, with the same restitution (0.883): ten times fewer steps
# for a statistic that does not depend on the stiffness here. Snapshots every 0.1 sqrt(d/g).
set -- --set chute.length=10 --set chute.width=5 --set chute.fill_height=6 --set chute.angle=26 \
  --set contact.normal_stiffness=2e3 --set contact.normal_damping_rate=5 --set contact.tangential_damping_rate=5 \
  --set run.end_time=120 --set run.output_interval=10 --set chute.coarse_graining.start=30 \
  --set chute.coarse_graining.interval=0.1 --threads 1 --quiet
for pair in "1 2" "3 4"; do  # one-rank runs two at a time, one per core (base and run)
  for seed in $pair; do "$talus" run "$scenario" "$@" --set run.seed=$seed --out one_$seed & done
  wait
done
for seed in 1 2 3 4; do
  $mpirun -n 2 "$talus" run "$scenario" "$@" --set run.seed=$seed --out two_$seed
  $mpirun -n 4 "$talus" run "$scenario" "$@" --set run.seed=$seed --out four_$seed
done
/usr/bin/python3 - <<'PY'
import csv, json, math, statistics, sys
fail = []
seeds = [1, 2, 3, 4]
def window_mean(run, column):
    values = [float(r[column]) for r in csv.DictReader(open(run + "/chute_series.csv"))]
    if len(values) < 75:  # 90 sqrt(d/g) in blocks of about 1.1
        fail.append(f"{run}: only {len(values)} blocks in the window")
    return sum(values) / len(values)
def ensemble(group, column):
    means = [window_mean(f"{group}_{s}", column) for s in seeds]
    return statistics.mean(means), statistics.stdev(means) / math.sqrt(len(means))
for group, ranks in [("two", 2), ("four", 4)]:
    for s in seeds:
        summary = json.load(open(f"{group}_{s}/summary.json"))
        if summary["ranks"] != ranks:
            fail.append(f"{group}_{s}: ran on {summary['ranks']} ranks, not {ranks}")
        if summary["particles_moved_between_ranks"] == 0:
            fail.append(f"{group}_{s}: no particle crossed a cut")
for column in ["mean_velocity", "volume_fraction", "h"]:
    m1, s1 = ensemble("one", column)
    for group in ["two", "four"]:
        m, s = ensemble(group, column)
        # Welch's t for two means of 4 runs each (about 6 degrees of freedom): 3.7 is its
        # two-sided 1 % point, the chance that equal statistics look different.
        t = abs(m - m1) / math.hypot(s, s1)
        print(f"{column}: 1 rank {m1:.4f} +- {s1:.4f}, {group} ranks {m:.4f} +- {s:.4f}: t = {t:.2f}")
        if t > 3.7:
            fail.append(f"{column}: {group} ranks differ from one by t = {t:.1f}")
if fail:
    print("FAILED:", *fail, sep="\n  ")
    sys.exit(1)
print("steady chute on 1, 2 and 4 ranks, four seeds each: the same statistics")
PY
