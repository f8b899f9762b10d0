#!/usr/bin/env bash
# The default commands on a mold, seeds 1..N, one run at a time under nice -n 5 (the machine is
# shared); one CSV row per run.
# Usage: experiments/defaults/run.sh MOLD.yaml ALGORITHM(es|sms-emoa) SEEDS OUT.csv [extra optimize options]
set -euo pipefail
mold=$1 algo=$2 seeds=$3 csv=$4
shift 4
here=$(cd "$(dirname "$0")" && pwd)
mtcs=${MTCS:-$here/../../build/mtcs}
work=$(mktemp -d)
run_one() {
  local s=$1
  shift
  local out=$work/seed$s
  local extra=()
  [[ $algo == sms-emoa ]] && extra=(--algorithm sms-emoa)
  nice -n 5 /usr/bin/time -f %U -o "$out.cpu" "$mtcs" optimize "$mold" --seed "$s" --out "$out" --threads 1 --quiet "${extra[@]}" "$@" \
    >/dev/null 2>"$out.err" || true
}
for s in $(seq 1 "$seeds"); do
  run_one "$s" "$@"
done
python3 "$here/collect.py" "$mold" "$algo" "$work" "$seeds" >>"$csv"
rm -rf "$work"
