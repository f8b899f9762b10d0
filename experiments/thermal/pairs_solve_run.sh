#!/usr/bin/env bash
# Old (main before this branch) against new, side by side, one process at a time:
#   bash experiments/thermal/pairs_solve_run.sh OLD_BENCH NEW_BENCH > experiments/thermal/pairs_solve.csv
# A third argument "es" runs the ES rows alone.
# OLD_BENCH: mtcs-bench built from main (8e3ddcb) into /tmp; NEW_BENCH: build/mtcs-bench.
# Rows: binary, run, N, user_s, wall_s, maxrss_kb, load1 (the 1-minute load at the start).
# Each run's stdout stays in /tmp/pairs_solve_BINARY_RUN_N.out (the ES runs' best objective).
set -euo pipefail
cd "$(dirname "$0")/../.."
old=$1 new=$2
echo "binary,run,n,user_s,wall_s,maxrss_kb,load1"
one() {  # label binary run n args...
  local label=$1 bin=$2 run=$3 n=$4; shift 4
  local load; load=$(cut -d' ' -f1 /proc/loadavg)
  local t; t=$( { nice -n 5 /usr/bin/time -f "%U,%e,%M" "$bin" "$@" > /tmp/pairs_solve_${label}_${run}_${n}.out; } 2>&1 | tail -1)
  echo "$label,$run,$n,$t,$load"
}
runs=${3:-all}
if [ "$runs" != es ]; then
for n in 300 1000; do
  for b in old new; do
    bin=$old; [ $b = new ] && bin=$new
    one $b $bin evaluate_mutations $n evaluate experiments/thermal/plate_physics.yaml --threads 1 --evaluations $n --mutations
  done
done
fi
for n in 100 3000; do
  for b in old new; do
    bin=$old; [ $b = new ] && bin=$new
    one $b $bin optimize_es $n optimize experiments/thermal/plate_physics.yaml --algorithm es --seeds 1 --evaluations $n
  done
done
