#!/usr/bin/env bash
# A cold Release build of the mtcs binary alone (ccache off), with and without the unity build,
# under Ninja so that .ninja_log gives each translation unit's time.
# Usage (from the checkout): bash experiments/ci/cold_build.sh OUTDIR
#   OUTDIR/{unity,files}.tsv: seconds per translation unit (start, end, object); the totals on stdout.
set -euo pipefail
out=${1:?usage: cold_build.sh OUTDIR}
mkdir -p "$out"
for mode in files unity; do
  tree=$(mktemp -d)
  unity=OFF; [ "$mode" = unity ] && unity=ON
  cmake -S . -B "$tree" -G Ninja -DCMAKE_BUILD_TYPE=Release -DMTCS_UNITY_BUILD=$unity \
    -DMTCS_BUILD_TESTS=OFF -DMTCS_BUILD_BENCH=OFF >/dev/null
  start=$(date +%s.%N)
  CCACHE_DISABLE=1 ninja -C "$tree" -j2 mtcs >/dev/null
  end=$(date +%s.%N)
  awk -F'\t' 'NR > 1 {printf "%.1f\t%.1f\t%s\n", $1 / 1000, $2 / 1000, $4}' "$tree/.ninja_log" > "$out/$mode.tsv"
  printf '%s: %.0f s wall, %d steps, %.0f s summed over steps\n' "$mode" "$(awk -v a="$start" -v b="$end" 'BEGIN {print b - a}')" \
    "$(wc -l < "$out/$mode.tsv")" "$(awk -F'\t' '{s += $2 - $1} END {print s}' "$out/$mode.tsv")"
  rm -rf "$tree"
done
