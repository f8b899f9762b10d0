#!/usr/bin/env bash
# SMS-EMOA against pagmo's NSGA-II on ZDT1-4, ZDT6, DTLZ1-2: mu = 100, 20 000 evaluations, 11
# seeds, in the same run; CPU seconds (load-independent) and hypervolume per run.
# Usage: bash experiments/optimize/sms_speed/run.sh   (after building mtcs-bench)
set -euo pipefail
cd "$(dirname "$0")/../../.."
out=experiments/optimize/sms_speed/results.csv
echo "problem,algorithm,seed,evaluations,hypervolume,seconds,cpu_seconds" > "$out"
for p in zdt1 zdt2 zdt3 zdt4 zdt6 dtlz1 dtlz2; do
  ./build/mtcs-bench sms-emoa --problem "$p" --seeds 11 --evaluations 20000 --algorithms sms-emoa,nsga2 | tail -n +2 >> "$out"
done
