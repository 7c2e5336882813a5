#!/usr/bin/env bash
# A study's Slurm job array on a real one-node cluster (tests/slurm/local_cluster.sh): `python3 -m
# talus ensemble --slurm` (the package built beside TALUS, TALUS doing the runs) writes the array,
# Slurm runs its three tasks, and the last one to end writes ensemble.json with all three runs. Exits 77 (skip) without Slurm or root, like
# test_local_cluster.sh. usage: test_study_array.sh TALUS
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
talus=$(realpath "$1")
export PYTHONPATH="$(dirname "$talus")/python${PYTHONPATH:+:$PYTHONPATH}"
for c in munged slurmctld slurmd sbatch; do
  if ! command -v "$c" >/dev/null; then echo "SKIP: $c not installed; run scripts/install-slurm.sh"; exit 77; fi
done
if [ "$(id -u)" -ne 0 ]; then echo "SKIP: needs root to run slurmd"; exit 77; fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
cp "$here/../data/five_spheres_drop.toml" drop.toml
/usr/bin/python3 -m talus ensemble drop.toml --seeds 3 --out out --talus "$talus" --slurm ensemble.sbatch --slurm-time 5:00
grep -q '^#SBATCH --array=0-2$' ensemble.sbatch
grep -q '^#SBATCH --time=5:00$' ensemble.sbatch
"$here/local_cluster.sh" ensemble.sbatch 240 | tee report.txt
[ "$(grep -c ' COMPLETED 0:0$' report.txt)" -eq 3 ]
for k in 1 2 3; do [ -f "out/seed_$k/summary.json" ] || { echo "FAIL: seed $k did not run"; exit 1; }; done
/usr/bin/python3 -c 'import json, sys; e = json.load(open("out/ensemble.json")); sys.exit(0 if e["runs"] == 3 else "runs: %s" % e["runs"])'
ls out/slurm-*_0.log out/slurm-*_2.log >/dev/null
echo "study array: 3 tasks on Slurm, ensemble.json of 3 runs"
