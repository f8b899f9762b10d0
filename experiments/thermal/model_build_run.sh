#!/usr/bin/env bash
# The line-sink model's build, old binary against new, alternating (model_build.md): wall and
# CPU seconds of mtcs thermal (--json and --out field.vtp) and of the demo's three steps on
# molds/plate.yaml, 2 cores. Prints CSV: round,binary,command,wall_s,user_s
# usage: bash experiments/thermal/model_build_run.sh OLD_MTCS NEW_MTCS [rounds]
set -euo pipefail
cd "$(dirname "$0")/../.."
old=$1 new=$2 rounds=${3:-2}
out=$(mktemp -d)
"$new" optimize molds/plate.yaml --evaluations 6000 --seed 1 --out "$out/layout" --quiet > /dev/null 2>&1
L=$out/layout/best.layout.yaml
echo "round,binary,command,wall_s,user_s"
t() {  # label binary command...
  local label=$1 b=$2
  shift 2
  /usr/bin/time -f "%e,%U" -o "$out/t" "$@" > "$out/$b.$label.out" 2>&1
  echo "$r,$b,$label,$(tail -1 "$out/t")"
}
for r in $(seq 1 "$rounds"); do
  for b in old new; do
    bin=$old; [ "$b" = new ] && bin=$new
    rm -rf "$out/D" "$out/field.vtp"
    t thermal_json $b "$bin" thermal molds/plate.yaml --layout "$L" --json
    t thermal_field $b "$bin" thermal molds/plate.yaml --layout "$L" --out "$out/field.vtp"
    t demo_optimize $b "$bin" optimize molds/plate.yaml --config configs/es_default.yaml --evaluations 10000 --seed 1 --polish 500 --out "$out/D"
    t demo_evaluate $b "$bin" evaluate molds/plate.yaml --layout "$out/D/best.layout.yaml"
    t demo_report $b "$bin" report "$out/D" --out "$out/D/report.html"
  done
done
# The outputs the two binaries print (the last round's): temperatures and objectives.
for label in thermal_json demo_evaluate; do
  if cmp -s "$out/old.$label.out" "$out/new.$label.out"; then echo "# $label: same output"; else
    echo "# $label: outputs differ:"; diff "$out/old.$label.out" "$out/new.$label.out" | grep -v seconds | head -20 | sed "s/^/# /" || true; fi
done
rm -rf "$out"
