#!/usr/bin/env bash
# Re-measures every figure README.md states (and the docs' that a short run can) on this machine,
# keeps the values in experiments/claims/last.json and renders experiments/CLAIMS.md.
#   bash scripts/claims.sh [--only STEP ...]     (after scripts/build.sh with the bench: ~10 min)
# An idle machine gives figures worth quoting: the throughputs and wall times are this machine's.
set -euo pipefail
cd "$(dirname "$0")/.."
for b in build/mtcs build/mtcs-bench; do
  [ -x "$b" ] || { echo "claims.sh: $b is missing: bash scripts/build.sh -DMTCS_BUILD_BENCH=ON first" >&2; exit 2; }
done
exec python3 scripts/claims.py run "$@"
