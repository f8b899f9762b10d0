#!/usr/bin/env bash
# ctest: the report of a small run on the physics plate (generation 0: feasible and infeasible
# layouts, violated clearances, points of the front that overlap) opened in headless chromium by
# report_page.mjs; the coolant and the cavity temperature of a short run on the bundled plate
# (--coolant --temperature); then the
# interference page of two meshes by interference_page.mjs.
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
# The bundled plate (a flow and temperature objectives): each circuit's heat, the bores by coolant temperature.
"$mtcs" optimize "$src/molds/plate.yaml" --evaluations 60 --seed 3 --out "$work/run_coolant" --quiet
"$mtcs" report "$work/run_coolant" --out "$work/report_coolant.html" --quiet
node "$src/tests/report/report_page.mjs" "$work/report_coolant.html" --coolant --temperature
# The plate with blind bores allowed from below, started from its layout plus a bubbler and a
# baffle: the report draws their inserts and names them in the bores' table.
sed 's/  allowed_faces: \[+x, -x, +y, -y\]/  allowed_faces: [+x, -x, +y, -y]\n  baffles: {faces: [-z]}/' \
  "$src/molds/plate.yaml" > "$work/plate_baffles.yaml"
grep -q "baffles:" "$work/plate_baffles.yaml"
{ grep -v '^#' "$src/molds/plate.layout.yaml"
  printf '  - {diameter: 10, kind: bubbler, waypoints: [[117.5, 100, 0], [117.5, 100, 91]]}\n'
  printf '  - {diameter: 10, kind: baffle, waypoints: [[182.5, 100, 0], [182.5, 100, 91]]}\n'; } > "$work/plate_baffles.layout.yaml"
"$mtcs" optimize "$work/plate_baffles.yaml" --start "$work/plate_baffles.layout.yaml" --evaluations 30 --seed 3 \
  --out "$work/run_baffles" --quiet
"$mtcs" report "$work/run_baffles" --no-temperature --out "$work/report_baffles.html" --quiet
node "$src/tests/report/report_page.mjs" "$work/report_baffles.html" --baffles
# The interference page: homer against the gear at the certified overlap placement; the pair
# count it must list is the certified one (tests/data/mesh_interference.csv).
row=$(grep '^homer,mcad_herringbone_gear,' "$src/tests/data/mesh_interference.csv" | awk -F, '$6 > 0' | head -1)
IFS=, read -r _ _ tx ty tz pairs _ <<<"$row"
"$mtcs" interfere "$src/tests/data/meshes/homer.off" "$src/tests/data/meshes/mcad_herringbone_gear.off" \
  --translate "$tx,$ty,$tz" --report "$work/interference.html" >/dev/null
node "$src/tests/report/interference_page.mjs" "$work/interference.html" "$pairs"
