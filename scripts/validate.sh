#!/bin/sh
# The papers' results (validation/REPORT.md, its figures, validation/huet2021/runout.json):
#   scripts/validate.sh            regenerates the report from the compact results committed
#                                  under validation/ (no simulation runs)
#   scripts/validate.sh run [...]  runs the cases still missing first (resumable: finished runs are
#                                  kept, an interrupted one runs again), options as
#                                  tools/validation.py run (--jobs N, --only FAMILY,..., --runs DIR;
#                                  --slurm DIR writes Slurm job arrays instead of running)
#   scripts/validate.sh compact [--runs DIR]
#                                  keeps the finished runs' compact results (after Slurm jobs, or
#                                  while a study still runs), then regenerates the report
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
if [ "${1:-}" = "run" ]; then
  shift
  [ -x "$root/build/talus" ] || cmake --build "$root/build" --target talus talus_python
  exec /usr/bin/python3 "$root/tools/validation.py" run "$@"
fi
if [ "${1:-}" = "compact" ]; then
  shift
  exec /usr/bin/python3 "$root/tools/validation.py" compact "$@"
fi
exec /usr/bin/python3 "$root/tools/validation.py" report
