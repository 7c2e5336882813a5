#!/usr/bin/env bash
# Configures and builds Talus in Release mode into build/ (installing dependencies first).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)"
