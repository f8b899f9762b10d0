#!/usr/bin/env bash
# mtcs's ES, SMS-EMOA and random search against pagmo's NSGA-II, MOEA/D, CMA-ES and NLopt's
# ISRES, CRS2 (fixed topology: each seed's first random layout) on two molds, 11 seeds, at
# budgets of 5 000 and 20 000 evaluations. Two processes at a time (one per mold).
# Usage: bash experiments/optimize/peers_run.sh [BUDGET ...]   (after building mtcs-bench)
set -euo pipefail
cd "$(dirname "$0")/../.."
out=experiments/optimize/peers
mkdir -p "$out"
budgets=("${@:-5000 20000}")
for budget in ${budgets[@]}; do
  for mold in plate_wall_distance cup; do
    ./build/mtcs-bench optimize "molds/$mold.yaml" --algorithm es sms-emoa random isres crs2 cmaes nsga2 moead \
      --seeds 11 --evaluations "$budget" --config configs/es_default.yaml \
      --trace "$out/trace_${mold}_${budget}.csv" > "$out/results_${mold}_${budget}.csv" 2> "$out/reference_${mold}.txt" &
  done
  wait
done
