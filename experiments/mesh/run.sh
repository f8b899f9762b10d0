#!/usr/bin/env bash
# Cylinder vs closed mesh: ours against FCL 0.7 on the six bundled meshes and their certified cases.
# Usage: bash experiments/mesh/run.sh   (after scripts/build.sh)
set -euo pipefail
cd "$(dirname "$0")/../.."
args=()
for m in fandisk_large turbine bunny00 homer mcad_herringbone_gear openscad_example006; do
  args+=(--mesh "tests/data/meshes/$m.off" --cases "tests/data/mesh_clearance/$m.csv")
done
./build/mtcs bench clearance "${args[@]}" --repeat 10 --builds 5 > experiments/mesh/clearance.csv
