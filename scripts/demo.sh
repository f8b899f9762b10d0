#!/usr/bin/env bash
# The demo: installs dependencies, builds, and runs the distance kernel on the bundled certified
# cylinder pairs, printing the benchmark table (ours against FCL, in the same run). The mold
# optimisation demo replaces this once `mtcs optimize` exists.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
pairs=tests/data/cylinder_pairs_public.csv
echo
echo "== mtcs distance: 43 000 certified cylinder pairs =="
./build/mtcs distance --pairs "$pairs" --out build/demo_distances.csv
echo "distances written to build/demo_distances.csv"
echo
echo "== mtcs bench distance (median/p99 ns per query, max error against the certified interval) =="
./build/mtcs bench distance --pairs "$pairs" --variants full,bounded-U5,fcl,segment-floor --repeat 4 | column -s, -t
