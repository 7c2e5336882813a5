#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/build.sh
cd build
# Tests run one at a time: several use both cores, and results are checked across thread counts.
ctest --output-on-failure --timeout 1200
