#!/usr/bin/env bash
# Quality at an equal evaluation budget: 4 islands (threads; ring, migration every 5
# generations, 2 migrants) against one population, the ES with the default config, 11 seeds, on
# two molds. Budget per run (all islands together): 2000 evaluations. Prints CSV of each run's
# best weighted objective (smaller is better) from summary.json.
set -euo pipefail
cd "$(dirname "$0")/../.."
MTCS=${MTCS:-build/mtcs}
BUDGET=${BUDGET:-2000}
out=$(mktemp -d)
echo "mold,variant,seed,best_objective,feasible"
for mold in plate_wall_distance cup; do
  for seed in $(seq 1 11); do
    for variant in one islands4; do
      dir=$out/$mold-$variant-$seed
      extra=""
      [ "$variant" = islands4 ] && extra="--islands 4 --migration-every 5 --migrants 2"
      $MTCS optimize molds/$mold.yaml --seed "$seed" --evaluations "$BUDGET" --out "$dir" $extra >/dev/null 2>&1
      python3 -c "import json,sys; s=json.load(open('$dir/summary.json')); print('$mold,$variant,$seed,%.6g,%s' % (s['best_objective'], s['feasible']))"
    done
  done
done
rm -rf "$out"
