#!/usr/bin/env bash
# Sensitivity of the ES and SMS-EMOA to their settings (issue 14, item 4): a full 2^4 factorial
# around the shipped defaults (configs/es_default.yaml), 11 seeds, 20 000 evaluations, on two
# molds with wall-distance objectives (plate_wall_distance, gear). Factors, low level = default:
#   pop      mu 10, lambda 40        | mu 20, lambda 80   (SMS-EMOA: population es.mu)
#   rates    insert/remove .1, snap/diameter .05, circuit .02 | all doubled
#   moves    mutation.moves 2         | 1
#   penalty  the spec's (constrained_domination) | static_linear
# One process at a time under nice -n 5 (a shared machine). The SMS-EMOA reference point is fixed
# per mold (the default config's, printed by mtcs-bench) so hypervolumes compare across configs.
# Usage: bash experiments/optimize/sensitivity/run.sh [BENCH]   (after building mtcs-bench)
set -euo pipefail
cd "$(dirname "$0")/../../.."
bench=${1:-./build/mtcs-bench}
dir=experiments/optimize/sensitivity
cfgdir=$(mktemp -d)
trap 'rm -rf "$cfgdir"' EXIT
out=$dir/results.csv
echo "config,pop,rates,moves,penalty,mold,algorithm,seed,evaluations,best_objective,feasible,seconds,hypervolume" > "$out"
declare -A ref=([plate_wall_distance]="[45.3938, 22.3597, 0.688316]" [gear]="[20.124, 9.26967, 0.566937]")
for mold in plate_wall_distance gear; do
  for pop in 0 1; do for rates in 0 1; do for moves in 0 1; do for penalty in 0 1; do
    name="p${pop}r${rates}m${moves}q${penalty}"
    cfg=$cfgdir/$mold-$name.yaml
    {
      echo "ref: ${ref[$mold]}"
      if [ $pop = 1 ]; then echo "es: {mu: 20, lambda: 80}"; fi
      if [ $penalty = 1 ]; then echo "penalty: static_linear"; fi
      echo "mutation:"
      if [ $rates = 1 ]; then echo "  {insert: 0.2, remove: 0.2, snap: 0.1, diameter: 0.1, circuit: 0.04, moves: $((moves ? 1 : 2))}"
      else echo "  {moves: $((moves ? 1 : 2))}"; fi
    } > "$cfg"
    nice -n 5 "$bench" optimize "molds/$mold.yaml" --algorithm es sms-emoa --seeds 11 --evaluations 20000 --config "$cfg" 2>/dev/null \
      | tail -n +2 | sed "s/^/$name,$pop,$rates,$moves,$penalty,/" >> "$out"
  done; done; done; done
done
