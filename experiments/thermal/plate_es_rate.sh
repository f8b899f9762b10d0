#!/usr/bin/env bash
# Issue 11's loop target on molds/plate.yaml (physics objectives, T2d): the ES run's own
# evaluations per second on one thread (the model's build excluded: the run's figure starts
# after it), old binary against new, alternating; and the user seconds of the whole command
# (the build included). Seeds 1-3, 20 000 evaluations.
# Prints CSV: round,binary,seed,evaluations,run_seconds,evaluations_per_second,user_seconds,load1
# usage: bash experiments/thermal/plate_es_rate.sh OLD_MTCS NEW_MTCS [rounds] [evaluations]
# OLD_MOLD=, NEW_MOLD= give each binary its own spec (default molds/plate.yaml): one binary, two
# settings. OLD_CONFIG=, NEW_CONFIG= give each its own run config (`mtcs optimize --config`; default
# none). ALGORITHM=sms-emoa times the SMS-EMOA instead of the ES.
set -euo pipefail
cd "$(dirname "$0")/../.."
old=$1 new=$2 rounds=${3:-2} budget=${4:-20000}
out=$(mktemp -d)
echo "round,binary,seed,evaluations,run_seconds,evaluations_per_second,user_seconds,load1"
for r in $(seq 1 "$rounds"); do
  for s in 1 2 3; do
    for b in old new; do
      bin=$old mold=${OLD_MOLD:-molds/plate.yaml} config=${OLD_CONFIG:-}
      [ "$b" = new ] && bin=$new mold=${NEW_MOLD:-molds/plate.yaml} config=${NEW_CONFIG:-}
      rm -rf "$out/run"
      /usr/bin/time -f "%U" -o "$out/user" nice -n 5 "$bin" optimize "$mold" --out "$out/run" --seed "$s" ${config:+--config "$config"} \
        --algorithm "${ALGORITHM:-es}" --threads 1 --evaluations "$budget" > "$out/log" 2>&1
      line=$(grep "feasible best\|best layout" "$out/log" | tail -1)
      evals=$(echo "$line" | sed -E 's/.* ([0-9]+) evaluations in ([0-9.]+) s.*/\1/')
      secs=$(echo "$line" | sed -E 's/.* ([0-9]+) evaluations in ([0-9.]+) s.*/\2/')
      rate=$(python3 -c "print(round($evals / $secs))")
      echo "$r,$b,$s,$evals,$secs,$rate,$(tail -1 "$out/user"),$(cut -d' ' -f1 /proc/loadavg)"
    done
  done
done
rm -rf "$out"
