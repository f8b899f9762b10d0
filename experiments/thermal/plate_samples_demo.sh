#!/usr/bin/env bash
# The bundled demo's optimisation (scripts/demo.sh: ES, configs/es_default.yaml, 10 000
# evaluations, seed 1) through mtcs-bench, CPU seconds: the old binary on the old plate.yaml, the
# new binary on the old plate.yaml (the heat-input change alone) and on the new one.
#   bash experiments/thermal/plate_samples_demo.sh OLD_BENCH NEW_BENCH OLD_PLATE.yaml OUT.csv [ROUNDS]
set -euo pipefail
old=$1 new=$2 old_plate=$3 out=$4 rounds=${5:-2}
echo "round,binary,mold,user_s,best_objective,hypervolume,load1" > "$out"
for r in $(seq "$rounds"); do
  for run in "old $old $old_plate" "new $new $old_plate" "new $new molds/plate.yaml"; do
    set -- $run
    line=$( { /usr/bin/time -f "user %U" nice -n 5 "$2" optimize "$3" --algorithm es --config configs/es_default.yaml \
              --seeds 1 --evaluations 10000; } 2>&1 | grep -E "^(user|$3)")
    u=$(echo "$line" | sed -n 's/^user //p') res=$(echo "$line" | grep -v "^user" | cut -d, -f5,8)
    echo "$r,$1,$(basename "$3"),$u,$res,$(cut -d' ' -f1 /proc/loadavg)" | tee -a "$out"
  done
done
