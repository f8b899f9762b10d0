#!/usr/bin/env bash
# Regenerates every figure of this study from the bundled certified pairs.
# Usage: bash experiments/distance/run.sh   (after scripts/build.sh)
set -euo pipefail
cd "$(dirname "$0")/../.."
pairs=tests/data/cylinder_pairs_public.csv
out=experiments/distance
./build/mtcs bench distance --pairs "$pairs" --repeat 16 > "$out/bench.csv"
./build/mtcs bench tolerance --pairs "$pairs" --repeat 16 > "$out/tolerance.csv"
./build/mtcs bench stiff --pairs "$pairs" --repeat 4 > "$out/stiff.csv"
/usr/bin/python3 scripts/plot_tolerance.py "$out/tolerance.csv" "$out/tolerance.png"
