#!/usr/bin/env bash
# ES against random search and NLopt's ISRES on a fixed topology (the seed's first random sample;
# "nlopt-ref": the hand-made reference layout's topology and coordinates as the start) on the
# plate and the cup: 11 seeds each, 20 000 evaluations per run.
# Usage: bash experiments/optimize/run.sh   (after scripts/build.sh; a few minutes)
set -euo pipefail
cd "$(dirname "$0")/../.."
out=experiments/optimize
echo "mold,algorithm,seed,evaluations,best_objective,feasible,seconds" > "$out/results.csv"
for mold in plate cup; do
  for alg in es random nlopt; do
    ./build/mtcs bench optimize "molds/$mold.yaml" --algorithm "$alg" --seeds 11 --evaluations 20000 \
      --config configs/es_default.yaml --trace "$out/trace_${mold}_${alg}.csv" | tail -n +2 >> "$out/results.csv"
  done
  ./build/mtcs bench optimize "molds/$mold.yaml" --algorithm nlopt --seeds 11 --evaluations 20000 \
    --topology "molds/$mold.layout.yaml" --trace "$out/trace_${mold}_nlopt-ref.csv" \
    | tail -n +2 | sed 's/,nlopt,/,nlopt-ref,/' >> "$out/results.csv"
done
/usr/bin/python3 scripts/plot_convergence.py "$out"
