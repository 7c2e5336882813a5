#!/usr/bin/env bash
# Installs what is missing, builds, and runs the default scenario: its results folder gets
# summary.json, timeseries.csv and a picture (energies.png).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/build.sh
scenario=${1:-examples/settling_box.toml}
out=results/$(basename "$scenario" .toml)
./build/talus run "$scenario" --out "$out" --overwrite
/usr/bin/python3 tools/plot_timeseries.py "$out"
echo "results: $out (summary.json, timeseries.csv, energies.png)"
