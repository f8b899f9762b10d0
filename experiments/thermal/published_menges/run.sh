#!/usr/bin/env bash
# The cooling-channel row attributed to Menges et al. (README.md here), by every tier mtcs has.
# Usage: bash experiments/thermal/published_menges/run.sh   (from the repository; ~6 min, 3.3 GB
# for the 0.5 mm finite volumes)
set -euo pipefail
cd "$(dirname "$0")/../../.."
here=experiments/thermal/published_menges
mtcs=${MTCS:-./build/mtcs}
for spec in row_flux row_coupled; do
  for run in "t2d" "fd --cell 2" "fd --cell 1" "fd --cell 0.5"; do
    [ "$spec" = row_coupled ] && [ "$run" = "fd --cell 0.5" ] && continue
    echo "== $spec, --tier $run"
    "$mtcs" thermal "$here/$spec.yaml" --layout "$here/row.layout.yaml" --tier $run \
      --samples "$here/line.csv" --out "/tmp/menges_${spec}_${run// /_}.csv" 2>&1 | grep -E "mean|cycle|condition|seconds"
    cut -d, -f4 "/tmp/menges_${spec}_${run// /_}.csv" | tr '\n' ' '
    echo
  done
done
