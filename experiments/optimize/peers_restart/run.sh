#!/usr/bin/env bash
# The ES arm only (the peers' rows in ../peers_moves/ do not depend on the ES), with the run
# config CONFIG, labelled LABEL, on the cells given as mold:budget (default: all seven cells of
# ../peers_moves/: cup, plate_wall_distance and gear at 20k and 100k, thermal_block at 20k).
# One process at a time, nice 5, 11 seeds.
# Usage: bash experiments/optimize/peers_restart/run.sh LABEL CONFIG [mold:budget ...]
#        (after MTCS_BUILD_TARGET=mtcs-bench bash scripts/build.sh; MTCS_BENCH=path: another binary)
set -euo pipefail
cd "$(dirname "$0")/../../.."
out=experiments/optimize/peers_restart
bench=${MTCS_BENCH:-./build/mtcs-bench}
label=$1 config=$2
shift 2
cells=("$@")
[ ${#cells[@]} -gt 0 ] || cells=(plate_wall_distance:100000 gear:100000 cup:100000 cup:20000 plate_wall_distance:20000
                                  gear:20000 thermal_block:20000)
for cell in "${cells[@]}"; do
  mold=${cell%%:*} budget=${cell##*:}
  nice -n 5 "$bench" optimize "molds/$mold.yaml" --algorithm es --seeds 11 --evaluations "$budget" \
    --config "$config" --trace "$out/trace_${mold}_${budget}_${label}.csv" \
    > "$out/results_${mold}_${budget}_${label}.csv" 2> /dev/null
done
