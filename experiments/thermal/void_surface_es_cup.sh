#!/usr/bin/env bash
# Does optimising the void-aware temperatures pay on the cup? ES, equal budget, seeds 1..N: the
# temperature objectives (molds/cup.yaml as bundled: t2d with cavity_void: surface) against the
# wall distances (the same spec with use: [uniformity, worst_covered, cost]); each run's best
# layout re-scored by the finite volumes at 2 mm (T3). Usage:
#   bash experiments/thermal/void_surface_es_cup.sh MTCS OUT.csv [SEEDS] [EVALUATIONS]
set -euo pipefail
mtcs=$1 out=$2 seeds=${3:-5} evaluations=${4:-2000}
here=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp "$here/molds/cup.yaml" "$work/temperatures.yaml"
sed 's/^  use: \[temperature_std, temperature_max, cost\]/  use: [uniformity, worst_covered, cost]/' \
  "$here/molds/cup.yaml" > "$work/wall_distances.yaml"
ln -s "$here/molds/meshes" "$work/meshes"
echo "arm,seed,t3_std_k,t3_mean_c,t3_max_c,feasible,seconds" > "$out"
for seed in $(seq 1 "$seeds"); do
  for arm in temperatures wall_distances; do
    start=$(date +%s.%N)
    "$mtcs" optimize "$work/$arm.yaml" --seed "$seed" --threads 1 --evaluations "$evaluations" --quiet \
      --out "$work/run_${arm}_$seed" > /dev/null
    seconds=$(echo "$(date +%s.%N) - $start" | bc)
    "$mtcs" thermal "$work/temperatures.yaml" --layout "$work/run_${arm}_$seed/best.layout.yaml" --tier fd --cell 2 \
      --json > "$work/t3.json"
    feasible=$("$mtcs" evaluate "$work/temperatures.yaml" --layout "$work/run_${arm}_$seed/best.layout.yaml" --json |
      python3 -c 'import json,sys; print(json.load(sys.stdin)["feasible"])')
    python3 - "$work/t3.json" "$arm" "$seed" "$feasible" "$seconds" >> "$out" <<'P'
import json, sys
t = json.load(open(sys.argv[1]))
print(f"{sys.argv[2]},{sys.argv[3]},{t['std']:.3f},{t['mean']:.2f},{t['max']:.2f},{sys.argv[4]},{float(sys.argv[5]):.1f}")
P
  done
done
cat "$out"
