#!/usr/bin/env bash
# Configures and builds Talus in Release mode into build/ (installing dependencies first).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
# TALUS_NATIVE=ON scripts/build.sh: tuned for this CPU (CMakeLists.txt, option TALUS_NATIVE).
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DTALUS_NATIVE="${TALUS_NATIVE:-OFF}" >/dev/null
cmake --build build -j"$(nproc)"
