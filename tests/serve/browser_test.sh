#!/usr/bin/env bash
# ctest: two users review one mold in headless chromium against a real `mtcs serve` on
# 127.0.0.1 (any free port): review_page.mjs drives both pages. The certified pair count of
# homer against the gear (tests/data/mesh_interference.csv) is what the check must report.
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
cd "$work"  # a relative --data, as docs/serve.md shows it
for u in olga:owner dora:designer rita:reviewer; do
  echo "${u%%:*}-password" | "$mtcs" serve --data data --add-user "${u%%:*}" --role "${u#*:}" >/dev/null
done
"$mtcs" serve --data data --port 0 > "$work/serve.log" 2>&1 &
server=$!
trap 'kill $server 2>/dev/null || true; wait $server 2>/dev/null || true' EXIT
for _ in $(seq 100); do
  grep -q "listening on" "$work/serve.log" && break
  sleep 0.1
done
url=$(sed -n 's/^mtcs serve: listening on \(http:[^ ]*\).*/\1/p' "$work/serve.log")
[ -n "$url" ] || { echo "FAILED: the server did not start:"; cat "$work/serve.log"; exit 1; }
row=$(grep '^homer,mcad_herringbone_gear,' "$src/tests/data/mesh_interference.csv" | awk -F, '$6 > 0' | head -1)
IFS=, read -r _ _ tx ty tz pairs _ <<<"$row"
# The corrected gear: every vertex 100 mm further along x (OFF: the vertex lines follow the counts).
awk 'NR == 1 { print; next } NR == 2 { n = $1; print; next } n > 0 && NF >= 3 { printf "%.17g %s %s\n", $1 + 100, $2, $3; n--; next } { print }' \
  "$src/tests/data/meshes/mcad_herringbone_gear.off" > "$work/gear.off"
node "$src/tests/serve/review_page.mjs" "$url" "$src/tests/data/meshes" "$work/gear.off" "$tx,$ty,$tz" "$pairs"
