#!/usr/bin/env bash
# Refreshes the three.js files the report page inlines (src/report/assets/three/) from the
# version pinned in web/package-lock.json: the build needs no network, only this script does.
# Files are copied unchanged; the page maps three.module.min.js's import of
# "./three.core.min.js" to the inlined core (src/report/html_page.cpp).
set -euo pipefail
cd "$(dirname "$0")/.."
npm ci --prefix web --no-audit --no-fund
from=web/node_modules/three
to=src/report/assets/three
mkdir -p "$to"
cp "$from/build/three.core.min.js" "$from/build/three.module.min.js" "$from/LICENSE" "$to/"
cp "$from/examples/jsm/controls/OrbitControls.js" "$to/"
node -p "'three ' + require('./web/node_modules/three/package.json').version" > "$to/VERSION"
echo "vendored $(cat "$to/VERSION") into $to"
