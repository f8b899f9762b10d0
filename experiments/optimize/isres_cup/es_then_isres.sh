#!/usr/bin/env bash
# ES for ES_BUDGET evaluations on the cup, then ISRES for ISRES_BUDGET on the ES best's topology,
# started at it; seeds 1-11 (README.md here). CSV on stdout: seed,es_best,isres_best,isres_feasible
# usage: bash experiments/optimize/isres_cup/es_then_isres.sh ES_BUDGET ISRES_BUDGET > OUT.csv
set -euo pipefail
cd "$(dirname "$0")/../../.."
es_budget=$1 isres_budget=$2
work=$(mktemp -d)
echo "seed,es_best,isres_best,isres_feasible"
for s in $(seq 1 11); do
  d=$work/seed$s
  ./build/mtcs optimize molds/cup.yaml --config configs/es_default.yaml --evaluations "$es_budget" --seed "$s" \
    --threads 1 --out "$d" --quiet > /dev/null 2>&1
  es_best=$(python3 -c "import json; print(json.load(open('$d/summary.json'))['best_objective'])")
  row=$(./build/mtcs-bench optimize molds/cup.yaml --algorithm isres --topology "$d/best.layout.yaml" --seeds 1 \
    --evaluations "$isres_budget" 2>/dev/null | tail -1)
  echo "$s,$es_best,$(echo "$row" | cut -d, -f5),$(echo "$row" | cut -d, -f6)"
done
rm -rf "$work"
