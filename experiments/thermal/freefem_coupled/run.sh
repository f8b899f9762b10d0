#!/bin/bash
# FreeFem++ 3-D reference for the coupled cavity condition (cup, gear, L-bracket), from the spec
# copies to tests/data/thermal/freefem_coupled_MOLD.csv. Re-runnable; ~1.3 h on 2 idle cores
# (the gear's P2 solves take ~10 and ~20 min, the L-bracket's ~3 and ~5).
#   bash experiments/thermal/freefem_coupled/run.sh [cup|gear ...]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../.." && pwd)
data=$root/tests/data/thermal
py=/usr/bin/python3                       # Debian's python3 (has numpy)
command -v FreeFem++ >/dev/null || apt-get install -y freefem++ libfreefem++
export FF_LOADPATH=/usr/lib/freefem++     # Debian's /etc/freefem++.pref points at a missing folder
mkdir -p "$here/work" && cd "$here/work"

molds=${*:-cup gear l_bracket}
for mold in $molds; do
  # 1. the conduction problem (block, faces, cavity triangles, samples) as mtcs sees it; the
  #    bundled layout only satisfies the CLI: its bores are replaced by the channel CSV.
  "$root/build/mtcs" thermal "$here/${mold}_coupled.yaml" --layout "$root/molds/$mold.layout.yaml" \
      --problem "${mold}_problem.json" > "${mold}_mtcs.txt"
  ch=$data/freefem_coupled_${mold}_channels.csv
  # 2. the channels keep >= 3 mm of steel to the cavity, each other and the block faces
  $py "$here/model.py" check "${mold}_problem.json" "$ch"
  # 3. two meshes: cavity/bore edge parameter H (mean edge ~0.6 H), block faces HB, tet volume VMAX
  #    (the gear's own tiny triangles make tetgen refine a lot: its levels are one step coarser)
  if [ "$mold" = gear ]; then levels=("coarse 5 12 200" "fine 3 10 100")
  else levels=("coarse 3 10 100" "fine 2 8 50"); fi
  for lev in "${levels[@]}"; do
    set -- $lev
    $py "$here/model.py" build "${mold}_problem.json" "$ch" "$2" "$3" "${mold}_$1"
    /usr/bin/time -f "$mold $1: %e s wall, %M kB max RSS" \
      FreeFem++ -nw -v 0 "$here/solve.edp" "$mold" "$1" "$4" 12 > "${mold}_$1.ffout" 2>&1
    tail -1 "${mold}_$1.ffout"
    cat "${mold}_$1.log"
  done
  # 4. convergence table; the finest P2 at the samples goes to tests/data
  $py "$here/model.py" collect "$mold" . "$data/freefem_coupled_${mold}.csv"
done
