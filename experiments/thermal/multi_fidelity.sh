#!/usr/bin/env bash
# Multi-fidelity against single-fidelity T2d at (about) equal CPU time, on the reference block
# (molds/thermal_block.yaml, one objective: temperature_std). Modes:
#   single  every offspring scored by T2d (M = 4), BUDGET evaluations
#   t1      offspring screened by T1, the best 10 of 40 re-scored by T2d, BUDGET_MF evaluations
#   t2d2    offspring screened by T2d with M = 2, the best 10 re-scored by T2d (M = 4), BUDGET_MF
# Every run's best layout is re-scored by finite volumes at CELL mm (fidelity.final_cell:
# summary.json "t3"). One thread, seeds 1..11. Writes multi_fidelity.csv.
#   bash experiments/thermal/multi_fidelity.sh [BUDGET] [BUDGET_MF] [CELL]
set -euo pipefail
cd "$(dirname "$0")/../.."
mtcs=${MTCS:-./build/mtcs}
budget=${1:-2000}
budget_mf=${2:-2400}
cell=${3:-2}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
out=experiments/thermal/multi_fidelity.csv
sed "s/^  use: .*/  use: [temperature_std]/" molds/thermal_block.yaml > "$work/block.yaml"
echo "fidelity: {final_cell: $cell}" > "$work/single.yaml"
echo "fidelity: {screen: t1, survivors: 10, final_cell: $cell}" > "$work/t1.yaml"
echo "fidelity: {screen: t2d, elements_per_bore: 2, survivors: 10, final_cell: $cell}" > "$work/t2d2.yaml"
echo "mode,seed,evaluations,cpu_seconds,t2d_std_k,t3_cell_mm,t3_seconds,t3_std_k,t3_mean_c" > "$out.tmp"
for seed in $(seq 1 11); do
  for mode in single t1 t2d2; do
    n=$budget
    [ "$mode" = single ] || n=$budget_mf
    dir="$work/$mode-$seed"
    # CPU seconds of the whole run, the final T3 solve included (the same in every mode): other
    # jobs share the machine, so wall time would measure them. t3_seconds: the solve's wall time.
    cpu=$( { /usr/bin/time -f "%U" "$mtcs" optimize "$work/block.yaml" --config "$work/$mode.yaml" --seed "$seed" \
             --evaluations "$n" --threads 1 --out "$dir" --quiet; } 2>&1 | tail -1)
    python3 -c "
import json, sys
j = json.load(open(sys.argv[1]))
t3 = j['t3']
print('$mode,$seed,%d,%.3f,%.4f,%g,%.3f,%.4f,%.4f' % (j['evaluations'], $cpu, j['objectives']['temperature_std'],
      t3['cell_mm'], t3['seconds'], t3['std'], t3['mean']))" "$dir/summary.json" >> "$out.tmp"
  done
done
mv "$out.tmp" "$out"
python3 - "$out" <<'PY'
import csv, statistics, sys
rows = list(csv.DictReader(open(sys.argv[1])))
print("mode | evaluations | median CPU s | median T2d std K | median T3 std K | range T3 std")
for mode in ["single", "t1", "t2d2"]:
    r = [x for x in rows if x["mode"] == mode]
    t3 = [float(x["t3_std_k"]) for x in r]
    print(mode, r[0]["evaluations"], "%.2f" % statistics.median(float(x["cpu_seconds"]) for x in r),
          "%.3f" % statistics.median(float(x["t2d_std_k"]) for x in r), "%.3f" % statistics.median(t3),
          "%.3f-%.3f" % (min(t3), max(t3)), sep=" | ")
PY
