#!/usr/bin/env bash
# Evaluations per second of random layouts (3 circuits x 8 axis-parallel bores) on every
# bundled mold, one thread and two. Usage: bash experiments/evaluate/run.sh (after a build)
set -euo pipefail
cd "$(dirname "$0")/../.."
out=experiments/evaluate
: > "$out/throughput.csv"
: > "$out/stages.csv"
first=1
for mold in plate cup l_bracket ribbed_box gear extreme; do
  ./build/mtcs bench evaluate "molds/$mold.yaml" --threads 2 --evaluations 20000 \
    > "$out/tmp.csv" 2> "$out/tmp_stages.csv"
  if [ $first = 1 ]; then head -1 "$out/tmp.csv" >> "$out/throughput.csv"; echo "mold,stage,microseconds_per_evaluation" >> "$out/stages.csv"; first=0; fi
  tail -n +2 "$out/tmp.csv" >> "$out/throughput.csv"
  tail -n +2 "$out/tmp_stages.csv" | sed "s|^|$mold,|" >> "$out/stages.csv"
done
rm -f "$out/tmp.csv" "$out/tmp_stages.csv"
cat "$out/throughput.csv"
