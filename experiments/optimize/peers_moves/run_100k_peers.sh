#!/usr/bin/env bash
# The 100 000-evaluation cells run_100k.sh left out: MOEA/D on cup and plate_wall_distance, and
# the gear with es, nsga2 and moead. One process at a time, nice 5, 11 seeds; the ES counts the
# reach move's evaluations in its budget (since 5d24ecb).
# Usage: bash experiments/optimize/peers_moves/run_100k_peers.sh   (MTCS_BENCH=path: another binary)
set -euo pipefail
cd "$(dirname "$0")/../../.."
out=experiments/optimize/peers_moves
bench=${MTCS_BENCH:-./build/mtcs-bench}
nice -n 5 "$bench" optimize molds/gear.yaml --algorithm es nsga2 moead --seeds 11 --evaluations 100000 \
  --config configs/es_default.yaml --trace "$out/trace_gear_100000.csv" > "$out/results_gear_100000.csv" 2> /dev/null
for mold in cup plate_wall_distance; do
  nice -n 5 "$bench" optimize "molds/$mold.yaml" --algorithm moead --seeds 11 --evaluations 100000 \
    --config configs/es_default.yaml --trace "$out/trace_${mold}_100000_moead.csv" \
    > "$out/results_${mold}_100000_moead.csv" 2> /dev/null
done
