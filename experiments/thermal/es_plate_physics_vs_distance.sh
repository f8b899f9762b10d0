#!/usr/bin/env bash
# Does optimising the physics pay on a mold? The evolution strategy on molds/plate.yaml (its
# thermal section: ABS 3 mm, 29 kW/m^2 into the cavity's lower and side faces, 8 l/min water)
# with one objective, the default tier's temperature_std against the wall-distance objective
# `uniformity` (tier 0), the same budget, one thread per run, two seeds at a time; each run's
# best layout is then judged by the finite volumes (T3, `mtcs thermal --tier fd --cell CELL`):
# the std over the spec's objective surface (thermal.objective_surface, `heated` by default:
# the faces this mold half cools), the same surface for both arms, and over every cavity sample
# (t3_std_all_k, from the same solve). Writes es_plate_physics_vs_distance.csv (rewritten after
# every seed, so an interrupted study leaves the seeds it finished), then the rank-sum test.
#   bash experiments/thermal/es_plate_physics_vs_distance.sh [EVALUATIONS] [CELL] [SEEDS] [JOBS]
# OBJECTIVES="temperature_std" runs one arm only (its rows alone in the CSV); "spec" is an arm
# with molds/plate.yaml's own objectives (temperature_std, temperature_max, cost). FIELDS=DIR keeps the
# per-sample T2d and T3 fields of every best layout there, named as plate_diagnosis.py caches them.
# VOID=plane sets thermal.cavity_void: plane (the line sinks see the cavity as an adiabatic cut;
# experiments/thermal/void_plane.md) in both arms' specs (uniformity does not use it). LAYOUTS=DIR
# keeps the best layouts there instead of experiments/thermal/es_plate_layouts. WALL_IMAGES=n sets
# thermal.wall_images: n in both arms' specs (the line sinks' exact reflection levels; T3 and
# uniformity do not use it): experiments/thermal/plate_wall_images.md. CONFIG=FILE: the run config
# (`mtcs optimize --config`) of every run. FIRST_SEED=k runs seeds k..SEEDS instead of 1..SEEDS.
set -euo pipefail
cd "$(dirname "$0")/../.."
mtcs=${MTCS:-./build/mtcs}
budget=${1:-5000}
cell=${2:-2}
seeds=${3:-11}
jobs=${4:-2}
first=${FIRST_SEED:-1}
objectives=${OBJECTIVES:-temperature_std uniformity}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
out=${OUT:-experiments/thermal/es_plate_physics_vs_distance.csv}
layouts=${LAYOUTS:-experiments/thermal/es_plate_layouts}
mkdir -p "$layouts"
for objective in temperature_std uniformity spec; do
  if [ "$objective" = spec ]; then cp molds/plate.yaml "$work/spec.yaml"
  else sed "s/^  use: .*/  use: [$objective]/" molds/plate.yaml > "$work/$objective.yaml"; fi
  if [ -n "${VOID:-}" ]; then sed -i "s/^  tier: t2d$/  tier: t2d\n  cavity_void: $VOID/" "$work/$objective.yaml"; fi
  if [ -n "${WALL_IMAGES:-}" ]; then sed -i "s/^  tier: t2d$/  tier: t2d\n  wall_images: $WALL_IMAGES/" "$work/$objective.yaml"; fi
done
# Every cavity sample (the order of mtcs's sample_box), for the std over the whole surface.
python3 -c "
import sys; sys.path.insert(0, 'experiments/thermal')
import plate_diagnosis as d
open('$work/samples.csv', 'w').write('x,y,z\n' + ''.join('%r,%r,%r\n' % tuple(q['p']) for q in d.samples()))"
header="objective,seed,evaluations,seconds,surface,t2d_std_k,t3_cell_mm,t3_seconds,t3_std_k,t3_mean_c,t3_max_c,t3_std_all_k,bores"

run_seed() {
  local seed=$1 objective dir start seconds t2d t3 bores
  for objective in $objectives; do
    dir="$work/$objective-$seed"
    start=$(date +%s.%N)
    "$mtcs" optimize "$work/$objective.yaml" ${CONFIG:+--config "$CONFIG"} --seed "$seed" --evaluations "$budget" \
      --threads 1 --out "$dir" --quiet
    seconds=$(echo "$(date +%s.%N) - $start" | bc)
    t2d=$("$mtcs" thermal "$work/$objective.yaml" --layout "$dir/best.layout.yaml" --json \
          --samples "$work/samples.csv" --out "$dir/t2d.csv")
    t3=$("$mtcs" thermal "$work/$objective.yaml" --layout "$dir/best.layout.yaml" --tier fd --cell "$cell" --json \
         --samples "$work/samples.csv" --out "$dir/t3.csv")
    # Straight bores: one per pair of consecutive waypoints of a circuit.
    bores=$(( $(grep -c "^      - \[" "$dir/best.layout.yaml") - $(grep -c "diameter:" "$dir/best.layout.yaml") ))
    python3 -c "
import csv, json, sys
sys.path.insert(0, 'experiments/thermal')
import plate_diagnosis as d
a, b = json.loads(sys.argv[1]), json.loads(sys.argv[2])
assert a['surface'] == b['surface']
t = [float(r['T']) for r in csv.DictReader(open('$dir/t3.csv'))]
std_all, _ = d.wstd(t, [q['w'] for q in d.samples()])
print('$objective,$seed,$budget,%.2f,%s,%.4f,$cell,%.2f,%.4f,%.4f,%.4f,%.4f,$bores' % (
    $seconds, b['surface'], a['std'], b['seconds'], b['std'], b['mean'], b['max'], std_all))" "$t2d" "$t3" >> "$work/rows-$seed.csv"
    cp "$dir/best.layout.yaml" "$layouts/$objective-$seed.layout.yaml"
    if [ -n "${FIELDS:-}" ]; then
      mkdir -p "$FIELDS"
      cp "$dir/t2d.csv" "$FIELDS/$objective-$seed.t2d.csv"; echo "$t2d" > "$FIELDS/$objective-$seed.t2d.json"
      cp "$dir/t3.csv" "$FIELDS/$objective-$seed.fd$cell.csv"; echo "$t3" > "$FIELDS/$objective-$seed.fd$cell.json"
    fi
  done
  # The table so far, in seed order.
  (echo "$header"; for s in $(seq "$first" "$seeds"); do [ -f "$work/rows-$s.csv" ] && cat "$work/rows-$s.csv"; done; true) > "$out.tmp.$seed"
  mv "$out.tmp.$seed" "$out"
}
export -f run_seed
export mtcs budget cell seeds first work out header objectives layouts
seq "$first" "$seeds" | xargs -P "$jobs" -I{} bash -c 'run_seed {}'
python3 experiments/thermal/rank_sum.py "$out" || echo "one arm only: no test"
