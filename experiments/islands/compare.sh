#!/usr/bin/env bash
# Two mtcs binaries side by side under the same load: speedup.sh with OLD, then NEW, REPS times
# in turn (one repetition each), every run's CSV row and ratios into OUT/old-N.txt, OUT/new-N.txt.
#   OLD=/tmp/mtcs_old NEW=build/mtcs REPS=3 EVALS=60000 experiments/islands/compare.sh OUTDIR
set -euo pipefail
cd "$(dirname "$0")/../.."
OUT=${1:?output folder}
mkdir -p "$OUT"
for rep in $(seq 1 "${REPS:-3}"); do
  for which in old new; do
    bin=$([ "$which" = old ] && echo "${OLD:?}" || echo "${NEW:-build/mtcs}")
    MTCS=$bin REPS=1 bash experiments/islands/speedup.sh >"$OUT/$which-$rep.txt" 2>&1
  done
done
