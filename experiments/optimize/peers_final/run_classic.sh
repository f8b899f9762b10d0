#!/usr/bin/env bash
# CMA-ES (pagmo) and NLopt's ISRES and CRS2 on every mold at 20 000 and 100 000 evaluations
# (before: cup and plate at 5k and 20k only, with an older mold problem). Same settings as run.sh.
# Usage: bash experiments/optimize/peers_final/run_classic.sh   (MTCS_BENCH=path: another binary)
#   CELLS="mold:budget[:algorithms] ..." LABEL=classic_rest: only those cells (algorithms joined by
#   '+', default cmaes+isres+crs2), into results_*_LABEL.csv (compare.py reads them after classic).
set -euo pipefail
cd "$(dirname "$0")/../../.."
out=experiments/optimize/peers_final
bench=${MTCS_BENCH:-./build/mtcs-bench}
label=${LABEL:-classic}
cells=${CELLS:-"cup:20000 plate_wall_distance:20000 gear:20000 thermal_block:20000 \
               cup:100000 plate_wall_distance:100000 gear:100000 thermal_block:100000"}
for cell in $cells; do
  IFS=: read -r mold budget algorithms <<< "$cell"
  IFS=+ read -r -a algorithms <<< "${algorithms:-cmaes+isres+crs2}"
  nice -n 5 "$bench" optimize "molds/$mold.yaml" --algorithm "${algorithms[@]}" --seeds 11 --evaluations "$budget" \
    --config configs/es_default.yaml --trace "$out/trace_${mold}_${budget}_${label}.csv" \
    > "$out/results_${mold}_${budget}_${label}.csv" 2> "$out/stderr_${mold}_${budget}_${label}.txt"
done
