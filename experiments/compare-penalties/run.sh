#!/usr/bin/env bash
# Penalty variants compared with SMS-EMOA on two bundled molds: all four variants, seeds 1..11,
# 20 000 evaluations per run, default run config (population 10), reference point (4, 4, 4) in
# scaled objectives. About 2 minutes on 2 cores. Writes plate/ and cup/ here.
set -euo pipefail
cd "$(dirname "$0")/../.."
for mold in plate cup; do
  out=experiments/compare-penalties/$mold
  rm -rf "$out"
  ./build/mtcs compare-penalties molds/$mold.yaml \
    --variants constrained_domination,static_linear,static_quadratic,death \
    --seeds 11 --evaluations 20000 --out "$out"
done
