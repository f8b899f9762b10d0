#!/usr/bin/env bash
# The ES as shipped after the reach move (configs/es_default.yaml: mutation.reach 0.05, which acts
# with worst_covered among the objectives) on the molds and budgets of run.sh and run_100k.sh,
# labelled es+reach; and the gear and the thermal block (temperature_std), where no peer had run,
# with es, nsga2 and moead at 20 000 evaluations. One process at a time, nice 5, 11 seeds.
# Usage: bash experiments/optimize/peers_moves/run_reach.sh   (after building mtcs-bench;
#        MTCS_BENCH=path picks another binary; PEER_MOLDS="gear" limits the second part)
# The reach move's own evaluations count in the budget since 5d24ecb (before, they did not).
set -euo pipefail
cd "$(dirname "$0")/../../.."
out=experiments/optimize/peers_moves
bench=${MTCS_BENCH:-./build/mtcs-bench}
for budget in 20000 100000; do
  for mold in cup plate_wall_distance; do
    nice -n 5 "$bench" optimize "molds/$mold.yaml" --algorithm es --seeds 11 --evaluations "$budget" \
      --config configs/es_default.yaml --trace "$out/trace_${mold}_${budget}_reach.csv" \
      > "$out/results_${mold}_${budget}_reach.csv" 2> /dev/null
  done
done
for mold in ${PEER_MOLDS:-gear thermal_block}; do
  nice -n 5 "$bench" optimize "molds/$mold.yaml" --algorithm es nsga2 moead --seeds 11 --evaluations 20000 \
    --config configs/es_default.yaml --trace "$out/trace_${mold}_20000.csv" \
    > "$out/results_${mold}_20000.csv" 2> "$out/reference_${mold}.txt"
done
