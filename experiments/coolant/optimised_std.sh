#!/usr/bin/env bash
# The coolant's warming in the model (thermal.coolant.rise) against a constant coolant, on what
# the optimiser finds: ES runs of the plate and the cup with the rise in the model and without it
# (same seeds, same budget), each best layout then solved by mtcs thermal with the rise (the
# physics: the coolant does warm). Usage:
#   experiments/coolant/optimised_std.sh [MTCS] [SEEDS] > optimised_std.csv
set -euo pipefail
cd "$(dirname "$0")/../.."
mtcs="$(realpath "${1:-build/mtcs}")"
seeds="${2:-5}"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
echo "mold,seed,evaluations,rise_in_search,objective,feasible,mean_C,std_K,max_C,cycle_s,largest_rise_K,run_s"
for mold in plate cup; do
  budget=4000
  [ "$mold" = cup ] && budget=2000
  for rise in true false; do
    sed -e "s/coolant: {temperature: 40, flow_rate: 8}/coolant: {temperature: 40, flow_rate: 8, rise: $rise}/" \
      -e "s#mesh: meshes/#mesh: $PWD/molds/meshes/#" "molds/$mold.yaml" > "$tmp/${mold}_$rise.yaml"
  done
  for seed in $(seq 1 "$seeds"); do
    for rise in true false; do
      out="$tmp/run_${mold}_${seed}_$rise"
      "$mtcs" optimize "$tmp/${mold}_$rise.yaml" --evaluations "$budget" --seed "$seed" --threads 1 --out "$out" --quiet
      # Judged with the rise, whichever model searched.
      "$mtcs" thermal "$tmp/${mold}_true.yaml" --layout "$out/best.layout.yaml" --json 2>/dev/null |
        /usr/bin/python3 -c "
import json, sys
j = json.load(sys.stdin)
s = json.load(open('$out/summary.json'))
rise = max(c['rise'] for c in j['coolant']['circuits'])
print('$mold,$seed,$budget,$rise,%.6g,%s,%.3f,%.4f,%.3f,%.2f,%.3f,%.1f' % (s['best_objective'], str(s['feasible']).lower(),
      j['mean'], j['std'], j['max'], j['cycle_time'], rise, s['seconds']))"
    done
  done
done
