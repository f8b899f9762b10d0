#!/usr/bin/env bash
# AM-guided vs unguided sampling and mutation on two angled-drilling molds, 11 seeds each, equal
# budget. Usage (from the repository root, after MTCS_BUILD_TARGET=mtcs bash scripts/build.sh):
#   bash experiments/access-map/am_guided.sh [OUT_DIR]
# Writes OUT_DIR/runs/... and experiments/access-map/am_guided.csv, am_guided.md.
set -euo pipefail
out=${1:-/tmp/mtcs_am_guided}
here=experiments/access-map
mkdir -p "$out/runs"
for mold in gear_angled cup_angled; do
  for arm in on off; do
    for seed in $(seq 1 11); do
      for kind in init es; do
        dir="$out/runs/${mold}_${kind}_${arm}_${seed}"
        rm -rf "$dir"
        ./build/mtcs optimize "$here/molds/$mold.yaml" --config "$here/am_guided/${kind}_${arm}.yaml" \
          --seed "$seed" --out "$dir" --quiet --threads 2
      done
    done
  done
done
python3 "$here/am_guided_summary.py" "$out/runs" "$here/am_guided.csv" > "$here/am_guided.md"
cat "$here/am_guided.md"
