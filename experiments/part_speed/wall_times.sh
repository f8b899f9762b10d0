#!/usr/bin/env bash
# What a user waits for on the bundled molds with a void (issue 41): the wall time and peak memory
# of `mtcs evaluate` and `mtcs thermal` of each mold's hand-made layout, for an older binary
# (no kept precomputes) and this one cold (an empty cache folder), warm (the folder the cold run
# filled) and with --no-cache. One run each, in turn, on an otherwise idle machine.
#   experiments/part_speed/wall_times.sh OLD_MTCS NEW_MTCS [MOLD ...] > wall_times.csv
set -euo pipefail
old=$1 new=$2
shift 2
molds=("$@")
[ ${#molds[@]} -gt 0 ] || molds=(cup gear l_bracket ribbed_box plate)
root=$(cd "$(dirname "$0")/../.." && pwd)
cache=$(mktemp -d)
trap 'rm -rf "$cache" "$cache.time"' EXIT
echo "mold,command,binary,seconds,peak_mb"
run() {  # mold command label binary [args...]
  local mold=$1 cmd=$2 label=$3 bin=$4
  shift 4
  local t
  /usr/bin/time -o "$cache.time" -f "%e %M" "$bin" "$cmd" "$root/molds/$mold.yaml" --layout "$root/molds/$mold.layout.yaml" \
    "$@" >/dev/null 2>&1
  t=$(tail -1 "$cache.time")
  echo "$mold,$cmd,$label,${t% *},$(( ${t#* } / 1024 ))"
}
for mold in "${molds[@]}"; do
  for cmd in evaluate thermal; do
    rm -rf "${cache:?}"/*
    run "$mold" "$cmd" old "$old"
    run "$mold" "$cmd" no-cache "$new" --no-cache
    MTCS_CACHE_DIR=$cache run "$mold" "$cmd" cold "$new"
    MTCS_CACHE_DIR=$cache run "$mold" "$cmd" warm "$new"
  done
done
