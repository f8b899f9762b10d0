#!/usr/bin/env bash
# Page size and load/render time of the report in headless chromium (software WebGL):
# the demo run's page, and a page with a 100k-triangle part and 60 bores (large_page.py).
# Usage (from the repo root, after scripts/demo.sh): bash experiments/report/measure.sh
set -euo pipefail
cd "$(dirname "$0")/../.."
out=experiments/report/results.csv
work=$(mktemp -d)
/usr/bin/time -f "%e" -o "$work/t_report" ./build/mtcs report runs/demo-plate --out "$work/demo.html" --quiet
/usr/bin/time -f "%e" -o "$work/t_report_nt" ./build/mtcs report runs/demo-plate --no-temperature --out "$work/demo_nt.html" --quiet
python3 experiments/report/large_page.py "$work/demo_nt.html" "$work/large.html" >/dev/null
echo "page,bytes,write_s,run,load_to_drawn_s,page_clock_s" > "$out"
for page in demo demo_nt large; do
  write=-
  [ "$page" = demo ] && write=$(cat "$work/t_report")
  [ "$page" = demo_nt ] && write=$(cat "$work/t_report_nt")
  for run in 1 2 3; do
    line=$(node tests/report/report_page.mjs "$work/$page.html" | grep "loaded and drawn")
    s=$(echo "$line" | sed -E 's/loaded and drawn in ([0-9.]+) s.*/\1/')
    c=$(echo "$line" | sed -E 's/.*page clock ([0-9.]+) s.*/\1/')
    echo "$page,$(stat -c %s "$work/$page.html"),$write,$run,$s,$c" >> "$out"
  done
done
column -s, -t "$out"
rm -rf "$work"
