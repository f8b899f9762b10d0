#!/usr/bin/env bash
# The ES with mutation.blend RATE (SBX of hole coordinates between parents of the same circuit
# shape, es_blendRATE.yaml) on the same molds, seeds and budget as run.sh; one process at a time.
# Usage: bash experiments/optimize/peers_moves/run_blend.sh [RATE [BUDGET]]   (after building mtcs-bench)
set -euo pipefail
cd "$(dirname "$0")/../../.."
out=experiments/optimize/peers_moves
rate=${1:-0.5} budget=${2:-20000}
for mold in cup plate_wall_distance; do
  nice -n 5 ./build/mtcs-bench optimize "molds/$mold.yaml" --algorithm es \
    --seeds 11 --evaluations "$budget" --config "$out/es_blend$rate.yaml" \
    --trace "$out/trace_${mold}_${budget}_blend$rate.csv" > "$out/results_${mold}_${budget}_blend$rate.csv" 2> /dev/null
done
