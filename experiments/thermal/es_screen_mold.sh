#!/usr/bin/env bash
# The screened ES (configs/es_screened.yaml) against the plain ES on a bundled mold with
# temperature objectives: seeds 1..N, equal budget, one thread per run, two runs at a time; each
# run's best layout solved by finite volumes (T3) at CELL mm and scored by the mold's own scalar
# objective with T3's temperatures (temperature_std / 1 + temperature_max / 10 + cost / 1000,
# molds/*.yaml's scales). Prints CSV rows, then the exact rank-sum test.
#   bash experiments/thermal/es_screen_mold.sh MOLD.yaml OUT.csv [SEEDS] [EVALUATIONS] [CELL]
set -euo pipefail
cd "$(dirname "$0")/../.."
mold=$1 out=$2 seeds=${3:-11} evaluations=${4:-2000} cell=${5:-2}
mtcs=${MTCS:-./build/mtcs}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
run_one() {
  local seed=$1 arm=$2 dir="$work/$2-$1" config=()
  [ "$arm" = screened ] && config=(--config configs/es_screened.yaml)
  "$mtcs" optimize "$mold" "${config[@]}" --seed "$seed" --threads 1 --evaluations "$evaluations" --quiet --out "$dir" > /dev/null
  "$mtcs" thermal "$mold" --layout "$dir/best.layout.yaml" --tier fd --cell "$cell" --json > "$dir/t3.json"
  "$mtcs" evaluate "$mold" --layout "$dir/best.layout.yaml" --json > "$dir/evaluation.json"
  python3 - "$dir" "$arm" "$seed" > "$work/row-$arm-$seed.csv" <<'P'
import json, sys
d, arm, seed = sys.argv[1:]
t, e, s = (json.load(open(f"{d}/{f}")) for f in ("t3.json", "evaluation.json", "summary.json"))
cost = e["objectives"]["cost"]
rate = s["evaluations"] / s["seconds"]
print(f"{arm},{seed},{t['std']:.4f},{t['max']:.3f},{cost:.1f},{t['std'] + t['max'] / 10 + cost / 1000:.4f},"
      f"{e['feasible']},{s['evaluations']},{s['seconds']:.3f},{rate:.0f}")
P
}
export -f run_one
export mtcs mold evaluations cell work
for s in $(seq 1 "$seeds"); do echo "$s plain"; echo "$s screened"; done | xargs -P 2 -L 1 bash -c 'run_one $0 $1'
(echo "arm,seed,t3_std_k,t3_max_c,cost,t3_fitness,feasible,evaluations,run_seconds,evaluations_per_second"
 cat "$work"/row-plain-*.csv "$work"/row-screened-*.csv | sort -t, -k1,1 -k2n) > "$out"
python3 - "$out" <<'P'
import csv, statistics, sys
sys.path.insert(0, "experiments/thermal")
from rank_sum import p_exact
rows = list(csv.DictReader(open(sys.argv[1])))
arm = {a: [r for r in rows if r["arm"] == a] for a in ("plain", "screened")}
for a, rs in arm.items():
    print(f"# {a}: median T3 fitness {statistics.median(float(r['t3_fitness']) for r in rs):.3f}, "
          f"std {statistics.median(float(r['t3_std_k']) for r in rs):.3f} K, "
          f"max {statistics.median(float(r['t3_max_c']) for r in rs):.2f} C, "
          f"rate {statistics.median(float(r['evaluations_per_second']) for r in rs):.0f}/s (two runs at a time), "
          f"feasible {sum(r['feasible'] == 'True' for r in rs)}/{len(rs)}")
a = [float(r["t3_fitness"]) for r in arm["screened"]]
b = [float(r["t3_fitness"]) for r in arm["plain"]]
u = sum((x < y) + 0.5 * (x == y) for x in a for y in b)
print(f"# U = {u:g} of {len(a) * len(b)} pairs have the screened layout fitter under T3; exact two-sided p = {p_exact(len(a), len(b), u):.2f}")
P
