#!/usr/bin/env bash
# Configures and builds Talus in Release mode into build/ (installing dependencies first).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
# TALUS_NATIVE=ON scripts/build.sh: tuned for this CPU; TALUS_ARCH=x86-64-v3 scripts/build.sh: for
# a micro-architecture level (cmake/talus_arch.cmake).
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DTALUS_NATIVE="${TALUS_NATIVE:-OFF}" -DTALUS_ARCH="${TALUS_ARCH:-}" >/dev/null
cmake --build build -j"$(nproc)"
