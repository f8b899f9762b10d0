#!/usr/bin/env bash
# Does optimising the physics pay? The evolution strategy on the reference block (molds/
# thermal_block.yaml: 2-5 through-bores along x) with the default tier's temperature_std against
# the same strategy with the wall-distance objective `uniformity` (tier 0), same budget, seeds
# 1..11; each run's best layout is then judged by the finite volumes at 1 mm (T3): the patch
# samples' std. Writes es_physics_vs_distance.csv; the summary and the rank-sum test: the .md.
#   bash experiments/thermal/es_physics_vs_distance.sh [EVALUATIONS]
set -euo pipefail
cd "$(dirname "$0")/../.."
budget=${1:-4000}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
out=experiments/thermal/es_physics_vs_distance.csv
for objective in temperature_std uniformity; do
  sed "s/^  use: .*/  use: [$objective]/" molds/thermal_block.yaml > "$work/$objective.yaml"
done
echo "objective,seed,evaluations,seconds,t3_std_k,t3_mean_c,t3_max_c,bores" > "$out.tmp"
for seed in $(seq 1 11); do
  for objective in temperature_std uniformity; do
    dir="$work/$objective-$seed"
    start=$(date +%s.%N)
    ./build/mtcs optimize "$work/$objective.yaml" --seed "$seed" --evaluations "$budget" --threads 1 --out "$dir" --quiet
    seconds=$(echo "$(date +%s.%N) - $start" | bc)
    json=$(./build/mtcs thermal "$work/$objective.yaml" --layout "$dir/best.layout.yaml" --tier fd --cell 1 --json)
    bores=$(grep -c "diameter:" "$dir/best.layout.yaml")
    python3 -c "import json,sys; j=json.loads(sys.argv[1]); print('$objective,$seed,$budget,$seconds,%.4f,%.4f,%.4f,$bores' % (j['std'], j['mean'], j['max']))" "$json" >> "$out.tmp"
  done
done
mv "$out.tmp" "$out"
python3 experiments/thermal/rank_sum.py "$out"
