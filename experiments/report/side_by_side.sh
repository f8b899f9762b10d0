#!/usr/bin/env bash
# Load time of report pages side by side: each page opened in turn, RUNS rounds, by
# tests/report/report_page.mjs (headless chromium, software WebGL), with the load average at
# each opening. Prints CSV: page,round,load1,load_to_drawn_s,page_clock_s,scripts_s,built_s,first_frame_s
# Usage (repo root): bash experiments/report/side_by_side.sh RUNS A.html B.html ...
set -euo pipefail
runs=$1; shift
echo "page,round,load1,load_to_drawn_s,page_clock_s,scripts_s,built_s,first_frame_s"
for round in $(seq "$runs"); do
  for page in "$@"; do
    load=$(cut -d' ' -f1 /proc/loadavg)
    line=$(node tests/report/report_page.mjs "$page" | grep "loaded and drawn")
    echo "$(basename "$page" .html),$round,$load,$(echo "$line" | sed -E 's/loaded and drawn in ([0-9.]+) s \(page clock ([0-9.]+) s: scripts parsed at ([0-9.]+) s, page built at ([0-9.]+) s, first frame ([0-9.]+) s.*/\1,\2,\3,\4,\5/')"
  done
done
