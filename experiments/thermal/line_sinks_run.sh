#!/usr/bin/env bash
# Re-measure the line-sink tiers (issue 11) on the block case: error against FreeFem++ P2 at the
# 720 patch samples, time per evaluation, and the ranking of 60 random layouts.
set -euo pipefail
cd "$(dirname "$0")/../.."
MTCS_BUILD_TARGET=thermal_tests bash scripts/build.sh >/dev/null
t=./build/tests/thermal_tests
$t "line sinks: error and time*" | grep -E "^(tier|T)" > experiments/thermal/line_sinks_block.csv
$t "line sinks: ranking*" | grep -E "^(tier|T)" > experiments/thermal/line_sinks_ranking.csv
$t "line sinks: best time*" | grep -B1 -A1 full_ms > experiments/thermal/line_sinks_best_time.csv
