#!/usr/bin/env bash
# Does moving a few holes per offspring (mutation.moves: 2) cost the ES quality against moving
# all of them (today's operator), at an equal evaluation budget? 11 seeds per mold and arm.
# Usage (from the repo root): bash experiments/evaluate/moves_study.sh [EVALUATIONS [OUT.csv]]
set -euo pipefail
cd "$(dirname "$0")/../.."
evals=${1:-5000}
out=${2:-experiments/evaluate/moves_study.csv}
default=$(mktemp --suffix=.yaml)
echo "evaluations: $evals" > "$default"
moves=$(mktemp --suffix=.yaml)
printf 'evaluations: %s\nmutation: {moves: 2}\n' "$evals" > "$moves"
echo "arm,mold,algorithm,seed,evaluations,best_objective,feasible,seconds" > "$out"
for mold in plate_wall_distance gear; do
  for arm in all moves2; do
    cfg=$default
    [ "$arm" = moves2 ] && cfg=$moves
    ./build/mtcs-bench optimize "molds/$mold.yaml" --algorithm es --config "$cfg" --seeds 11 --evaluations "$evals" \
      | tail -n +2 | sed "s/^/$arm,/" >> "$out"
  done
done
rm -f "$default" "$moves"
python3 experiments/evaluate/moves_summary.py "$out"
