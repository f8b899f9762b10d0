#!/usr/bin/env bash
# The demo: installs dependencies, builds, and optimises the cooling bores of the bundled plate
# mold (molds/plate.yaml) with the evolution strategy, then scores the result. The plate's
# objectives are temperatures (line sinks, 0.3-0.6 ms of CPU per ES child), so the budget is
# 10 000 evaluations: the three steps take 5-6 s on 2 cores (experiments/thermal/model_build.md),
# plus the first build.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
MTCS_BUILD_TARGET=mtcs bash scripts/build.sh  # the binary only: the tests build with scripts/test.sh
out=runs/demo-plate
rm -rf "$out"
echo
echo "== mtcs optimize molds/plate.yaml (plate 200 x 150 x 3 mm, 4 ejector pins; cavity temperature std, max, cost) =="
# configs/es_explore.yaml: more restarts and circuit moves, better than the default at this
# budget on the plate (configs/README.md).
./build/mtcs optimize molds/plate.yaml --config configs/es_explore.yaml --evaluations 10000 --seed 1 \
  --polish 500 --out "$out"
echo
echo "== mtcs evaluate: the best layout, re-scored =="
./build/mtcs evaluate molds/plate.yaml --layout "$out/best.layout.yaml"
echo
echo "== against the hand-made reference (molds/plate.layout.yaml), scored the same way =="
./build/mtcs evaluate molds/plate.yaml --layout "$out/best.layout.yaml" --json > "$out/best.evaluation.json"
./build/mtcs evaluate molds/plate.yaml --layout molds/plate.layout.yaml --json > "$out/reference.evaluation.json"
python3 - "$out/best.evaluation.json" "$out/reference.evaluation.json" <<'PY'
import json, sys
print(f"{'':<22}{'std [K]':>9}{'max [C]':>9}{'cost':>8}{'scalarised':>12}")
for name, path in (("optimised (10 000)", sys.argv[1]), ("hand-made reference", sys.argv[2])):
    j = json.load(open(path))
    o = j["objectives"]
    print(f"{name:<22}{o['temperature_std']:>9.2f}{o['temperature_max']:>9.2f}{o['cost']:>8.1f}{j['scalarised']:>12.3f}")
PY
echo "(lower is better; the ES beats the reference in some seeds and budgets, not all:"
echo " experiments/optimize/plate_demo/README.md)"
echo
echo "Results in $out/: best.layout.yaml (edit it and re-score with mtcs evaluate), bores.csv and"
echo "bores.stl (open in a CAD viewer, e.g. with the part), summary.json, run.sqlite (every generation)."
echo
echo "== mtcs report: the run as one HTML page (3-D view, Pareto front, convergence) =="
./build/mtcs report "$out" --out "$out/report.html"
echo "Open $(pwd)/$out/report.html in a browser (it needs no network): drag to orbit, click a front point to load its layout."
