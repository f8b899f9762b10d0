#!/usr/bin/env bash
# The samples keep the void panels' potentials, not their response S A^-1 (one LU solve per
# sample): `mtcs thermal` with and without --out, old binary against new, alternating.
# Prints CSV: round,binary,mold,mode,wall_s,user_s
# usage: bash experiments/thermal/void_potentials_time.sh OLD_MTCS NEW_MTCS [rounds]
set -euo pipefail
cd "$(dirname "$0")/../.."
old=$1 new=$2 rounds=${3:-3}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
echo "round,binary,mold,mode,wall_s,user_s"
for r in $(seq 1 "$rounds"); do
  for m in cup gear; do
    for mode in json out; do
      for b in old new; do
        bin=$old; [ "$b" = new ] && bin=$new
        args=(--json); [ "$mode" = out ] && args=(--out "$out/f.ply")
        /usr/bin/time -f "%e,%U" -o "$out/t" "$bin" thermal "molds/$m.yaml" --layout "molds/$m.layout.yaml" "${args[@]}" > /dev/null
        echo "$r,$b,$m,$mode,$(cat "$out/t")"
      done
    done
  done
done
