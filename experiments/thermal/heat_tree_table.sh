#!/usr/bin/env bash
set -euo pipefail
cd "$(dirname "$0")/../.."
# mtcs thermal on every bundled mold with a thermal section: old binary (direct sums) against new (tree)
# usage: bash experiments/thermal/heat_tree_table.sh OLD_MTCS NEW_MTCS > experiments/thermal/heat_tree.csv
# (prints no header: the CSV in git has it: mold,binary,samples,mean_C,std_K,max_C,wall_s,user_s)
for m in cup ribbed_box l_bracket gear plate thermal_block; do
  for b in "$1" "$2"; do
    [ "$m" = gear ] && [ "$b" = "$1" ] && continue  # the direct sums take more than 10 min there
    /usr/bin/time -f "%e %U" -o /tmp/ht_time timeout 900 "$b" thermal molds/$m.yaml --layout molds/$m.layout.yaml --json 2>/dev/null |
      python3 -c "import json,sys;d=json.load(sys.stdin);t=open('/tmp/ht_time').read().split();print('$m,'+('old' if '$b'=='$1' else 'new')+',%d,%.6f,%.6f,%.6f,%s,%s'%(d['samples'],d['mean'],d['std'],d['max'],t[0],t[1]))"
  done
done
