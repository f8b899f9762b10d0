#!/usr/bin/env bash
# Does optimising the physics pay on a mold? The evolution strategy on molds/plate.yaml (its
# thermal section: ABS 3 mm, 29 kW/m^2 into the cavity's lower and side faces, 8 l/min water)
# with one objective, the default tier's temperature_std against the wall-distance objective
# `uniformity` (tier 0), the same budget, seeds 1..11, one thread; each run's best layout is
# then judged by the finite volumes (T3, `mtcs thermal --tier fd --cell CELL`): the cavity
# samples' std. Writes es_plate_physics_vs_distance.csv, then the rank-sum test.
#   bash experiments/thermal/es_plate_physics_vs_distance.sh [EVALUATIONS] [CELL]
set -euo pipefail
cd "$(dirname "$0")/../.."
mtcs=${MTCS:-./build/mtcs}
budget=${1:-5000}
cell=${2:-2}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
out=experiments/thermal/es_plate_physics_vs_distance.csv
for objective in temperature_std uniformity; do
  sed "s/^  use: .*/  use: [$objective]/" molds/plate.yaml > "$work/$objective.yaml"
done
echo "objective,seed,evaluations,seconds,t2d_std_k,t3_cell_mm,t3_seconds,t3_std_k,t3_mean_c,t3_max_c,bores" > "$out.tmp"
for seed in $(seq 1 11); do
  for objective in temperature_std uniformity; do
    dir="$work/$objective-$seed"
    start=$(date +%s.%N)
    "$mtcs" optimize "$work/$objective.yaml" --seed "$seed" --evaluations "$budget" --threads 1 --out "$dir" --quiet
    seconds=$(echo "$(date +%s.%N) - $start" | bc)
    t2d=$("$mtcs" thermal "$work/$objective.yaml" --layout "$dir/best.layout.yaml" --json)
    t3=$("$mtcs" thermal "$work/$objective.yaml" --layout "$dir/best.layout.yaml" --tier fd --cell "$cell" --json)
    # Straight bores: one per pair of consecutive waypoints of a circuit.
    bores=$(( $(grep -c "^      - \[" "$dir/best.layout.yaml") - $(grep -c "diameter:" "$dir/best.layout.yaml") ))
    python3 -c "
import json, sys
a, b = json.loads(sys.argv[1]), json.loads(sys.argv[2])
print('$objective,$seed,$budget,%.2f,%.4f,$cell,%.2f,%.4f,%.4f,%.4f,$bores' % ($seconds, a['std'], b['seconds'], b['std'], b['mean'], b['max']))" "$t2d" "$t3" >> "$out.tmp"
    mkdir -p "experiments/thermal/es_plate_layouts"
    cp "$dir/best.layout.yaml" "experiments/thermal/es_plate_layouts/$objective-$seed.layout.yaml"
  done
done
mv "$out.tmp" "$out"
python3 experiments/thermal/rank_sum.py "$out"
