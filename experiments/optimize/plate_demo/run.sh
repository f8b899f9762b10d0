#!/usr/bin/env bash
# One arm of the plate demo study (README.md here): `mtcs optimize MOLD --config CONFIG` as the
# demo runs it (--polish 500), one seed at a time on one thread, a row per seed appended to
# results.csv (objective, bores, circuits, seconds, the objectives, the polish); run folders deleted.
#   bash experiments/optimize/plate_demo/run.sh VARIANT CONFIG MOLD BUDGET SEED...
# MTCS=path/to/mtcs (default ./build/mtcs); START=LAYOUT.yaml starts each run from that layout
# (mtcs optimize --start); RESULTS=FILE.csv appends there instead (the coupled plate's second
# objective is cycle_time, in the column the fixed-flux plate's temperature_max had).
set -euo pipefail
cd "$(dirname "$0")/../../.."
here=experiments/optimize/plate_demo
mtcs=${MTCS:-./build/mtcs}
v=$1 cfg=$2 mold=$3 budget=$4; shift 4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
results=${RESULTS:-$here/results.csv}
second=temperature_max
[ -n "${RESULTS:-}" ] && second=cycle_time
[ -f "$results" ] || echo "variant,config,mold,budget,seed,objective,feasible,bores,circuits,evaluations,es_seconds,wall_seconds,temperature_std,$second,cost,polish_improved,polish_before" > "$results"
for s in "$@"; do
  d=$work/run_${v}_${budget}_${s}
  t0=$(date +%s.%N)
  nice -n 5 "$mtcs" optimize "$mold" --config "$cfg" --evaluations "$budget" --seed "$s" --polish 500 --out "$d" --threads 1 --quiet ${START:+--start "$START"}
  t1=$(date +%s.%N)
  python3 - "$v" "$(basename "$cfg")" "$(basename "$mold")" "$budget" "$s" "$d" "$t0" "$t1" "$second" >> "$results" <<'PY'
import json, sys, csv
v, cfg, mold, budget, s, d, t0, t1, second = sys.argv[1:]
j = json.load(open(f"{d}/summary.json"))
rows = list(csv.DictReader(open(f"{d}/bores.csv")))
o = j["objectives"]
print(",".join(map(str, [v, cfg, mold, budget, s, j["best_objective"], int(j["feasible"]), len(rows),
    len({r["circuit"] for r in rows}), j["evaluations"], round(j["seconds"], 3), round(float(t1) - float(t0), 3),
    o["temperature_std"], o[second], o["cost"], int(j.get("polish", {}).get("improved", False)), j.get("polish", {}).get("before", "")])))
PY
  rm -rf "$d"
done
