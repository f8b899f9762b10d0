#!/usr/bin/env bash
# The ES (with its local moves, configs/es_default.yaml) against pagmo's NSGA-II and MOEA/D at
# 20 000 evaluations, 11 seeds, on cup and plate_wall_distance; one process at a time, nice 5.
# Usage: bash experiments/optimize/peers_moves/run.sh   (after building mtcs-bench)
set -euo pipefail
cd "$(dirname "$0")/../../.."
out=experiments/optimize/peers_moves
for mold in cup plate_wall_distance; do
  nice -n 5 ./build/mtcs-bench optimize "molds/$mold.yaml" --algorithm es nsga2 moead \
    --seeds 11 --evaluations 20000 --config configs/es_default.yaml \
    --trace "$out/trace_${mold}_20000.csv" > "$out/results_${mold}_20000.csv" 2> "$out/reference_${mold}.txt"
done
