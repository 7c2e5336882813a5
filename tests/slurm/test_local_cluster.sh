#!/usr/bin/env bash
# Checks tests/slurm/local_cluster.sh end to end: runs demo_array.sbatch (4 tasks) on the private
# one-node Slurm cluster and asserts each task wrote its file; then that a failing task makes the
# harness exit non-zero. Exits 77 (skip) when Slurm or munge is not installed
# (scripts/install-slurm.sh installs them) or when not root.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
for c in munged slurmctld slurmd sbatch; do
  if ! command -v "$c" >/dev/null; then
    echo "SKIP: $c not installed; run scripts/install-slurm.sh"; exit 77
  fi
done
if [ "$(id -u)" -ne 0 ]; then echo "SKIP: needs root to run slurmd"; exit 77; fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
pass=0 fail=0
check() { if "$@"; then pass=$((pass + 1)); else echo "FAIL: $*"; fail=$((fail + 1)); fi; }

rc=0
DEMO_OUT=$work/out "$here/local_cluster.sh" "$here/demo_array.sbatch" 120 >report.txt || rc=$?
cat report.txt
check [ "$rc" -eq 0 ]
for i in 0 1 2 3; do check grep -q "^task $i of job" "out/$i"; done
check [ "$(grep -c ' COMPLETED 0:0$' report.txt)" -eq 4 ]

rc=0
DEMO_OUT=$work/out2 DEMO_FAIL_TASK=2 "$here/local_cluster.sh" "$here/demo_array.sbatch" 120 \
  >report2.txt || rc=$?
cat report2.txt
check [ "$rc" -eq 3 ]
check grep -q '^2 FAILED 3:0$' report2.txt

echo "local_cluster: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
