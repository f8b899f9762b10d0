#!/usr/bin/env bash
# Baffles and bubblers on the cup (issue 42, item 5): ES runs of molds/cup.yaml as bundled (side-
# drilled circuits only) and with drilling.baffles (blind bores down into the core from +z), the
# same seeds and budget; each best layout then solved by mtcs thermal. Usage:
#   experiments/coolant/baffles_cup.sh [MTCS] [SEEDS] [EVALUATIONS] [JOBS] > baffles_cup.csv
# then experiments/coolant/baffles_summary.py baffles_cup.csv
set -euo pipefail
cd "$(dirname "$0")/../.."
mtcs="$(realpath "${1:-build/mtcs}")"
seeds="${2:-11}"
budget="${3:-6000}"
jobs="${4:-2}"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
sed -e "s#mesh: meshes/#mesh: $PWD/molds/meshes/#" molds/cup.yaml > "$tmp/without.yaml"
sed -e "s#mesh: meshes/#mesh: $PWD/molds/meshes/#" \
  -e "s#  allowed_faces: \[+x, -x, +y, -y\]#  allowed_faces: [+x, -x, +y, -y]\n  baffles: {faces: [+z], max: 2}#" \
  molds/cup.yaml > "$tmp/with.yaml"
grep -q "baffles:" "$tmp/with.yaml"
one() {
  local seed="$1" arm="$2" out="$tmp/run_$1_$2"
  "$mtcs" optimize "$tmp/$arm.yaml" --evaluations "$budget" --seed "$seed" --threads 1 --out "$out" --quiet
  "$mtcs" thermal "$tmp/with.yaml" --layout "$out/best.layout.yaml" --json 2>/dev/null > "$out/thermal.json"
  /usr/bin/python3 -c "
import json
j = json.load(open('$out/thermal.json'))
s = json.load(open('$out/summary.json'))
blind = open('$out/best.layout.yaml').read().count('kind:')
print('$arm,$seed,$budget,%.6g,%s,%d,%.3f,%.3f,%.4f,%.3f,%.3f,%s,%.1f' % (s['best_objective'], str(s['feasible']).lower(), blind,
      j['sides']['core']['mean'], j['mean'], j['std'], j['max'], j['cycle_time'], str(j['ejectable']).lower(), s['seconds']))"
}
export -f one
export mtcs tmp budget
echo "arm,seed,evaluations,objective,feasible,blind_bores,core_mean_C,mean_C,std_K,max_C,cycle_s,ejectable,run_s"
for seed in $(seq 1 "$seeds"); do for arm in with without; do echo "$seed $arm"; done; done |
  xargs -P "$jobs" -L 1 bash -c 'one "$0" "$1"' | sort -t, -k1,1 -k2,2n
