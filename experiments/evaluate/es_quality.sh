#!/usr/bin/env bash
# Does a change that moves objectives in their last bits change what the ES finds? Old binary
# against new, seeds 1-11, gear and plate_wall_distance, one thread: the best objective of each
# run. Prints CSV: binary,mold,seed,evaluations,best_objective.
# usage: bash experiments/evaluate/es_quality.sh OLD_MTCS NEW_MTCS [evaluations]
set -euo pipefail
cd "$(dirname "$0")/../.."
old=$1 new=$2 evals=${3:-20000}
out=$(mktemp -d)
echo "binary,mold,seed,evaluations,best_objective"
for m in gear plate_wall_distance; do
  for s in $(seq 1 11); do
    for b in old new; do
      bin=$old; [ "$b" = new ] && bin=$new
      rm -rf "$out/run"
      "$bin" optimize "molds/$m.yaml" --out "$out/run" --seed "$s" --threads 1 --evaluations "$evals" > "$out/log" 2>&1
      line=$(grep "feasible best\|best layout" "$out/log" | tail -1)
      echo "$b,$m,$s,$evals,$(echo "$line" | sed -E 's/.*objective ([0-9.e+-]+),.*/\1/')"
    done
  done
done
rm -rf "$out"
