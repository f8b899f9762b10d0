#!/usr/bin/env bash
# ctest: the report of a small plate run (generation 0: feasible and infeasible layouts, 3 to 12
# bores, violated clearances) opened in headless chromium by report_page.mjs.
# Exit 77 (ctest: skipped, with the reason printed) only when chromium is absent.
# Usage: browser_test.sh MTCS_BINARY SOURCE_DIR WORK_DIR
set -euo pipefail
mtcs=$1 src=$2 work=$3
if ! command -v node >/dev/null 2>&1; then
  echo "FAILED: node not found (scripts/setup.sh installs nodejs and the page's test tools)"
  exit 1
fi
rm -rf "$work"
mkdir -p "$work"
"$mtcs" optimize "$src/molds/plate_wall_distance.yaml" --evaluations 400 --seed 3 --out "$work/run" --quiet
"$mtcs" report "$work/run" --generation 0 --no-temperature --out "$work/report.html" --quiet
node "$src/tests/report/report_page.mjs" "$work/report.html"
