#!/usr/bin/env bash
# The default command on the first-mold part and every bundled mold, seeds 1-11, one run at a
# time (run.sh). The temperature molds (plate, thermal_block: 5-12 ms per layout) at 2 000
# evaluations instead of the default 20 000 (a 20 000-evaluation run costs 2-4 min each there).
# Usage: experiments/defaults/bundled.sh OUT.csv [STAGE...]   stages: part sms es temperature
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
csv=$1
shift
stages=${*:-part sms es temperature}
molds=$here/../../molds
[[ -s $csv ]] || echo "mold,algorithm,seed,feasible,circuits,bores,worst_covered_mm,objectives,front_size,distinct_front,hypervolume,warnings,cpu_s" >"$csv"
for stage in $stages; do
  case $stage in
    part)
      for algo in es sms-emoa; do bash "$here/run.sh" "$here/../../docs/first-mold/part.yaml" "$algo" 11 "$csv"; done ;;
    sms | es)
      algo=$([[ $stage == sms ]] && echo sms-emoa || echo es)
      for m in cup extreme gear l_bracket plate_wall_distance ribbed_box; do bash "$here/run.sh" "$molds/$m.yaml" "$algo" 11 "$csv"; done ;;
    temperature)
      for algo in sms-emoa es; do
        for m in plate thermal_block; do bash "$here/run.sh" "$molds/$m.yaml" "$algo" 11 "$csv" --evaluations 2000; done
      done ;;
  esac
done
