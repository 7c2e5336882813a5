#!/usr/bin/env bash
# Installs the Debian packages Talus needs, plus any named as arguments; quiet and quick when
# all are present.
set -euo pipefail
packages=(
  build-essential cmake pkg-config
  dpkg-dev file  # cpack -G DEB: dpkg-shlibdeps finds the packages' library dependencies
  libgtest-dev libgmock-dev libbenchmark-dev
  libtomlplusplus-dev libeigen3-dev libcli11-dev nlohmann-json3-dev libqhull-dev
  libhdf5-dev
  python3 python3-numpy python3-scipy python3-matplotlib
  pybind11-dev python3-dev python3-pytest  # the talus Python module (python/)
  python3-vtk9
  openmpi-bin libopenmpi-dev python3-mpi4py
)
packages+=("$@")  # what one caller alone needs, e.g. clang for scripts/fuzz.sh
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
