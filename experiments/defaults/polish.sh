#!/usr/bin/env bash
# --polish 1000 after the default ES on the first-mold part, seeds 1-11, one run at a time:
# one CSV row per seed (improved, before, after, why_not).
# Usage: experiments/defaults/polish.sh OUT.csv
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
mtcs=${MTCS:-$here/../../build/mtcs}
work=$(mktemp -d)
echo "seed,improved,before,after,evaluations,why_not" >"$1"
for s in $(seq 1 11); do
  nice -n 5 "$mtcs" optimize "$here/../../docs/first-mold/part.yaml" --seed "$s" --polish 1000 --out "$work/s$s" --threads 1 --quiet >/dev/null 2>&1 || true
  python3 -c "import json,sys;p=json.load(open('$work/s$s/summary.json'))['polish'];print(f\"$s,{int(p['improved'])},{p['before']:.6g},{p['after']:.6g},{p['evaluations']},\\\"{p.get('why_not','')}\\\"\")" >>"$1"
done
rm -rf "$work"
