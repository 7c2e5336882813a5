#!/bin/sh
# The papers' results (validation/REPORT.md, its figures, validation/huet2021/runout.json):
#   scripts/validate.sh            regenerates the report from the compact results committed
#                                  under validation/ (no simulation runs)
#   scripts/validate.sh run [...]  runs the cases still missing first (resumable: finished runs are
#                                  kept, an interrupted one runs again), options as
#                                  tools/validation.py run (--jobs N, --only FAMILY,..., --runs DIR)
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
if [ "${1:-}" = "run" ]; then
  shift
  [ -x "$root/build/talus" ] || cmake --build "$root/build" --target talus talus_python
  exec /usr/bin/python3 "$root/tools/validation.py" run "$@"
fi
exec /usr/bin/python3 "$root/tools/validation.py" report
