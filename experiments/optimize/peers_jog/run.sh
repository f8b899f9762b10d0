#!/usr/bin/env bash
# The ES and SMS-EMOA with the jog move on (configs/es_jog.yaml: the default config with
# mutation.jog 0.2), every mold of the peer matrix at 20 000 and 100 000 evaluations, 11 seeds; the
# peers' runs do not depend on the ES's mutation and stay those of ../peers_final (compare.py here).
# Usage: bash experiments/optimize/peers_jog/run.sh   (MTCS_BENCH=path: another binary)
set -euo pipefail
cd "$(dirname "$0")/../../.."
out=experiments/optimize/peers_jog
bench=${MTCS_BENCH:-./build/mtcs-bench}
for budget in 20000 100000; do
  for mold in cup plate_wall_distance gear thermal_block; do
    for alg in es sms-emoa; do
      layouts=()  # the best layouts kept for the cup at 100k only (README.md here)
      [ "$mold-$budget" = cup-100000 ] && layouts=(--layouts "$out/layouts_${mold}_${budget}")
      nice -n 5 "$bench" optimize "molds/$mold.yaml" --algorithm "$alg" --seeds 11 --evaluations "$budget" \
        --config configs/es_jog.yaml "${layouts[@]}" \
        > "$out/results_${mold}_${budget}_${alg}.csv" 2> "$out/stderr_${mold}_${budget}_${alg}.txt"
    done
  done
done
