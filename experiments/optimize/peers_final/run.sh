#!/usr/bin/env bash
# The cells the earlier peer runs left out (issue 14 item 3): SMS-EMOA at 100 000 evaluations on
# cup, plate_wall_distance and gear, at 20 000 on gear and thermal_block; and the thermal block
# (temperatures, T2d in the loop) at 100 000 for the shipped ES, NSGA-II, MOEA/D and SMS-EMOA.
# One process at a time, nice 5, 11 seeds, the shipped run config.
# Usage: bash experiments/optimize/peers_final/run.sh   (MTCS_BENCH=path: another binary)
set -euo pipefail
cd "$(dirname "$0")/../../.."
out=experiments/optimize/peers_final
bench=${MTCS_BENCH:-./build/mtcs-bench}
run() {  # mold budget label algorithms...
  local mold=$1 budget=$2 label=$3
  shift 3
  nice -n 5 "$bench" optimize "molds/$mold.yaml" --algorithm "$@" --seeds 11 --evaluations "$budget" \
    --config configs/es_default.yaml --trace "$out/trace_${mold}_${budget}_${label}.csv" \
    > "$out/results_${mold}_${budget}_${label}.csv" 2> "$out/stderr_${mold}_${budget}_${label}.txt"
}
for mold in cup plate_wall_distance gear; do run "$mold" 100000 sms sms-emoa; done
for mold in gear thermal_block; do run "$mold" 20000 sms sms-emoa; done
run thermal_block 100000 all es nsga2 moead sms-emoa
