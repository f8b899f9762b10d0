#!/usr/bin/env bash
# ctest: scripts/serve_demo.sh --check with the built mtcs: the server starts on the bundled molds,
# takes the four meshes and runs its check; the pairs it reports are what `mtcs interfere` finds.
# Usage: demo_test.sh MTCS_BINARY SOURCE_DIR WORK_DIR
set -euo pipefail
mtcs=$1 src=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
MTCS="$mtcs" MTCS_REVIEW_DATA="$work/data" bash "$src/scripts/serve_demo.sh" --check --port 0 | tee "$work/demo.out"
served=$(sed -n 's/.*: \([0-9]*\) intersecting triangle pairs.*/\1/p' "$work/demo.out")
direct=$("$mtcs" interfere "$src/molds/meshes/mcad_herringbone_gear.off" "$src/molds/meshes/cup.off" \
  --translate=-15,-90,-45 --json | python3 -c 'import json, sys; print(json.load(sys.stdin)["pair_count"])')
echo "served: $served pairs, mtcs interfere: $direct"
[ -n "$served" ] && [ "$served" = "$direct" ] && [ "$direct" -gt 0 ]
[ "$(grep -c '^uploaded ' "$work/demo.out")" = 4 ]
