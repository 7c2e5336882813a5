#!/usr/bin/env bash
# Installs the build into a fresh prefix in a temporary folder and uses it as a user would,
# from outside the source and build trees:
#   - a C++ project (this folder) finds the engine with find_package(Talus), builds and runs;
#   - the installed talus checks and runs installed examples and plots a run with the
#     installed Python package (PREFIX/lib/python3/dist-packages/talus, not build/python);
#   - with the Python module built, Debian's python3 imports it from PREFIX/lib/python3/dist-packages.
# The folder is removed when every check passed and kept for a look otherwise.
# Usage: test_install.sh CMAKE BUILD_DIR CXX_COMPILER PYTHON_MODULE(ON|OFF)
set -euo pipefail
cmake=$1 build=$2 cxx=$3 python_module=$4
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/talus_install_test.XXXXXX")
trap 'echo "install test: FAILED; its files are in $work"' ERR
prefix=$work/prefix
step() { echo "== $*"; }

step "cmake --install into $prefix"
"$cmake" --install "$build" --prefix "$prefix" >"$work/install.log"

step "the consumer project: configure, build, run"
"$cmake" -S "$here" -B "$work/consumer" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER="$cxx" \
         -DCMAKE_PREFIX_PATH="$prefix" >"$work/consumer_configure.log"
"$cmake" --build "$work/consumer" >"$work/consumer_build.log"
"$work/consumer/two_spheres"

cd "$work"
talus=$prefix/bin/talus
examples=$prefix/share/talus/examples
step "talus check and run on installed examples"
"$talus" check "$examples/two_sphere_impact.toml" >/dev/null
"$talus" check "$examples/cross_pile.toml" >/dev/null  # crosses: a shaped example
"$talus" run "$examples/two_sphere_impact.toml" --out run --quiet --threads 1
step "talus plot with the installed package"
"$talus" plot run >/dev/null
test -s run/energies.png
# The plot came from the installed package: without its plot module, the installed talus has no plot.
studies=$prefix/lib/python3/dist-packages/talus/studies
mv "$studies/plot_timeseries.py" "$work/"
if env -u PYTHONPATH "$talus" plot run >/dev/null 2>&1; then
  echo "talus plot ran without the installed plot_timeseries.py: it used another copy"
  false
fi
mv "$work/plot_timeseries.py" "$studies/"

if [ "$python_module" = ON ]; then
  step "import talus from $prefix/lib/python3/dist-packages"
  PYTHONPATH=$prefix/lib/python3/dist-packages PYTHONDONTWRITEBYTECODE=1 /usr/bin/python3 - "$prefix" <<'PY'
import sys
import talus
prefix = sys.argv[1]
assert talus.__file__.startswith(prefix), talus.__file__  # the installed copy, not build/python
s = talus.load(prefix + "/share/talus/examples/two_sphere_impact.toml")
s.run_until(0.02)  # through the collision: the spheres come back apart
x, v = s.positions[:, 0], s.velocities[:, 0]
left, right = (0, 1) if x[0] < x[1] else (1, 0)
assert v[left] < 0 < v[right], v
print(f"python: at t = {s.time:.3g} the spheres move apart at {v[left]:.3g} and {v[right]:.3g}")
PY
fi
rm -rf "$work"
echo "install test: ok"
