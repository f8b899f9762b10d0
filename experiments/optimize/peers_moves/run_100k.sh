#!/usr/bin/env bash
# 100 000 evaluations on the cup: the ES (defaults), NSGA-II, then the ES with mutation.blend 0.5;
# then the plate: the ES and NSGA-II. 11 seeds, one process at a time, nice 5.
# Usage: bash experiments/optimize/peers_moves/run_100k.sh   (after building mtcs-bench)
set -euo pipefail
cd "$(dirname "$0")/../../.."
out=experiments/optimize/peers_moves
nice -n 5 ./build/mtcs-bench optimize molds/cup.yaml --algorithm es nsga2 --seeds 11 --evaluations 100000 \
  --config configs/es_default.yaml --trace "$out/trace_cup_100000.csv" > "$out/results_cup_100000.csv" 2> /dev/null
nice -n 5 ./build/mtcs-bench optimize molds/cup.yaml --algorithm es --seeds 11 --evaluations 100000 \
  --config "$out/es_blend0.5.yaml" --trace "$out/trace_cup_100000_blend0.5.csv" > "$out/results_cup_100000_blend0.5.csv" 2> /dev/null
nice -n 5 ./build/mtcs-bench optimize molds/plate_wall_distance.yaml --algorithm es nsga2 --seeds 11 --evaluations 100000 \
  --config configs/es_default.yaml --trace "$out/trace_plate_wall_distance_100000.csv" \
  > "$out/results_plate_wall_distance_100000.csv" 2> /dev/null
