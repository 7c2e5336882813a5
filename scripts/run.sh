#!/usr/bin/env bash
# Installs what is missing, builds, and runs the default scenario (a small dam break of crosses):
# its results folder gets summary.json, the time series and measurements, and pictures.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/build.sh
scenario=${1:-examples/dam_break_small.toml}
out=results/$(basename "$scenario" .toml)
./build/talus run "$scenario" --out "$out" --overwrite
./build/talus plot "$out"
if [ -d "$out/vtk" ]; then
  ./build/talus render "$out" --view side --out "$out/final_side.png"
fi
echo "results: $out (summary.json, timeseries.csv, *.png)"
