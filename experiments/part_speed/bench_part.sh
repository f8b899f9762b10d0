#!/usr/bin/env bash
# `mtcs bench part` on every bundled mold with a part and on the held-out part (issue 41), this
# build against an older binary in the same run; one CSV (mold,program,measure,value,unit).
#   experiments/part_speed/bench_part.sh OLD_MTCS [--optimize] > bench_part.csv
set -euo pipefail
old=$1
shift
root=$(cd "$(dirname "$0")/../.." && pwd)
cd "$root"
echo "mold,program,measure,value,unit"
for mold in molds/cup.yaml molds/gear.yaml molds/l_bracket.yaml molds/ribbed_box.yaml molds/plate.yaml \
  experiments/part_speed/held_out/fandisk.yaml; do
  build/mtcs bench part "$mold" --peer "$old" --repeat 3 "$@" 2>/dev/null | tail -n +2
done
