#!/usr/bin/env bash
# One change's effect on an ES run's time when the VM drifts: per seed, the fastest of REPS runs
# of each binary, old and new alternating (a run is deterministic, so its fastest time is its
# cost plus the least noise). Only for changes that keep every bit: the two binaries must take
# the same path. Prints CSV: mold,seed,old_min_s,new_min_s,new_over_old.
# usage: bash experiments/evaluate/es_min_pairs.sh OLD_MTCS NEW_MTCS REPS MOLD EVALUATIONS SEED...
set -euo pipefail
cd "$(dirname "$0")/../.."
old=$1 new=$2 reps=$3 mold=$4 evals=$5
shift 5
out=$(mktemp -d)
echo "mold,seed,old_min_s,new_min_s,new_over_old"
for s in "$@"; do
  best_old=inf best_new=inf
  for _ in $(seq 1 "$reps"); do
    for b in old new; do
      bin=$old; [ "$b" = new ] && bin=$new
      rm -rf "$out/run"
      t=$("$bin" optimize "molds/$mold.yaml" --out "$out/run" --seed "$s" --threads 1 --evaluations "$evals" 2>&1 |
        grep "evaluations in" | sed -E 's/.* evaluations in ([0-9.]+) s.*/\1/')
      if [ "$b" = old ]; then best_old=$(python3 -c "print(min(float('$best_old'), $t))")
      else best_new=$(python3 -c "print(min(float('$best_new'), $t))"); fi
    done
  done
  echo "$mold,$s,$best_old,$best_new,$(python3 -c "print(round($best_new / $best_old, 3))")"
done
rm -rf "$out"
