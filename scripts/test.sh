#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/build.sh
./scripts/install-slurm.sh  # the Slurm job-array tests run a private one-node cluster
cd build
# Tests run one at a time: several use both cores, and results are checked across thread counts.
ctest --output-on-failure --timeout 1200
