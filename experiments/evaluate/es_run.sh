#!/usr/bin/env bash
# The ES run's own evaluations per second (issue 14, target 1), old binary against new,
# alternating: gear and plate_wall_distance, seeds 1-3, 100 000 evaluations, one thread, three
# rounds. Prints CSV: round,binary,mold,seed,evaluations,run_seconds,user_seconds,load1.
# usage: bash experiments/evaluate/es_run.sh OLD_MTCS NEW_MTCS [rounds]
set -euo pipefail
cd "$(dirname "$0")/../.."
old=$1 new=$2 rounds=${3:-3}
out=$(mktemp -d)
echo "round,binary,mold,seed,evaluations,run_seconds,user_seconds,load1"
for r in $(seq 1 "$rounds"); do
  for m in gear plate_wall_distance; do
    for s in 1 2 3; do
      for b in old new; do
        bin=$old; [ "$b" = new ] && bin=$new
        rm -rf "$out/run"
        /usr/bin/time -f "%U" -o "$out/user" nice -n 5 "$bin" optimize "molds/$m.yaml" --out "$out/run" --seed "$s" \
          --threads 1 --evaluations 100000 > "$out/log" 2>&1
        line=$(grep "feasible best\|best layout" "$out/log" | tail -1)
        evals=$(echo "$line" | sed -E 's/.* ([0-9]+) evaluations in ([0-9.]+) s.*/\1/')
        secs=$(echo "$line" | sed -E 's/.* ([0-9]+) evaluations in ([0-9.]+) s.*/\2/')
        echo "$r,$b,$m,$s,$evals,$secs,$(tail -1 "$out/user"),$(cut -d' ' -f1 /proc/loadavg)"
      done
    done
  done
done
rm -rf "$out"
