#!/usr/bin/env bash
# The coolant's warming along its circuits in the model (thermal.coolant.rise) against a
# constant coolant: a bundled mold's layout at 8 and 2 l/min per circuit, by the default tier
# (T2d) and the finite volumes at 2 mm (finer than the cup's 2.5 mm walls need).
# Usage: experiments/coolant/rise_effect.sh [MTCS] [MOLD] > rise_effect.csv   (MOLD: plate, cup, ...)
set -euo pipefail
cd "$(dirname "$0")/../.."
mtcs="$(realpath "${1:-build/mtcs}")"
mold="${2:-plate}"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
echo "flow_l_min,rise,tier,mean_C,std_K,max_C,cycle_s,heat_to_bores_W,rises_K,seconds"
for flow in 8 2; do
  for rise in true false; do
    sed -e "s/coolant: {temperature: 40, flow_rate: 8}/coolant: {temperature: 40, flow_rate: $flow, rise: $rise}/" \
      -e "s#mesh: meshes/#mesh: $PWD/molds/meshes/#" "molds/$mold.yaml" > "$tmp/mold.yaml"
    for tier in t2d fd; do
      "$mtcs" thermal "$tmp/mold.yaml" --layout "molds/$mold.layout.yaml" --tier "$tier" --cell 2 --json 2>/dev/null |
        /usr/bin/python3 -c "
import json, sys
j = json.load(sys.stdin)
r = ' '.join('%.3f' % c['rise'] for c in j['coolant']['circuits'])
print('$flow,$rise,$tier,%.3f,%.3f,%.3f,%.2f,%.1f,%s,%.1f' % (j['mean'], j['std'], j['max'], j['cycle_time'], j['heat_to_bores'], r, j['seconds']))"
    done
  done
done
