#!/bin/bash
# Kept from 2026-11-29 (experiments/optimize/isres_cup/README.md): usage es_then_isres.sh ES_BUDGET ISRES_BUDGET; paths are /work/main and /tmp/sr.
# ES for A evaluations, then ISRES on the ES best's topology (started at it) for B evaluations
A=$1; B=$2; out=/tmp/sr/hybrid_${A}_${B}.csv
echo "seed,es_best,isres_best,isres_feasible" > $out
for s in $(seq 1 11); do
  d=/tmp/sr/hy_${A}_$s; rm -rf $d
  /work/main/build/mtcs optimize /work/main/molds/cup.yaml --config /work/main/configs/es_default.yaml --evaluations $A --seed $s --threads 1 --out $d --quiet > /dev/null 2>&1
  esb=$(python3 -c "import json;d=json.load(open('$d/summary.json'));print(d['best_objective'] if 'best_objective' in d else d.get('objective'))")
  r=$(/work/main/build/mtcs-bench optimize /work/main/molds/cup.yaml --algorithm isres --topology $d/best.layout.yaml --seeds 1 --evaluations $B 2>/dev/null | tail -1)
  echo "$s,$esb,$(echo $r | cut -d, -f5),$(echo $r | cut -d, -f6)" >> $out
done
