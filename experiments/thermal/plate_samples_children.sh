#!/usr/bin/env bash
# CPU per child on a fixed set of children (the same layouts at every spacing, unlike the ES
# runs, whose paths part): mtcs-bench evaluate --mutations on one thread, 2 circuits of 3 legs
# (the ES's layouts; CIRCUITS, BORES to change), CPU per child = (user at E = 7000 - user at E = 1000) / 6000.
#   bash experiments/thermal/plate_samples_children.sh OLD_BENCH NEW_BENCH OUT.csv [ROUNDS] [SPACINGS]
set -euo pipefail
old=$1 new=$2 out=$3 rounds=${4:-3} spacings=${5:-"- 5.5 8 11 16.5"}
circuits=${CIRCUITS:-2} bores=${BORES:-3}
tmp=$(mktemp -d)
# The base spec: main's molds/plate.yaml (no thermal.sample_spacing), e.g.
# git show 3cca68c:molds/plate.yaml > /tmp/plate_old.yaml; PLATE=/tmp/plate_old.yaml bash ...
plate=${PLATE:-molds/plate.yaml}
grep -q "^  sample_spacing: .*" <(sed -n '/^thermal:/,$p' "$plate") && { echo "PLATE must not set thermal.sample_spacing" >&2; exit 2; }
echo "round,binary,spacing,evaluations,user_s,load1" > "$out"
for r in $(seq "$rounds"); do
  for s in $spacings; do
    bin=$new mold=$plate
    if [ "$s" = "-" ]; then bin=$old; else
      mold=$tmp/plate_$s.yaml
      sed "s/^  tier: t2d$/  tier: t2d\n  sample_spacing: $s/" "$plate" > "$mold"
    fi
    for n in 1000 7000; do
      /usr/bin/time -o "$tmp/user" -f %U nice -n 5 "$bin" evaluate "$mold" --threads 1 --mutations --circuits "$circuits" \
        --bores "$bores" --evaluations "$n" >/dev/null 2>&1
      u=$(tail -1 "$tmp/user")
      echo "$r,$([ "$s" = "-" ] && echo old || echo new),${s/-/cavity},$n,$u,$(cut -d' ' -f1 /proc/loadavg)" | tee -a "$out"
    done
  done
done
rm -rf "$tmp"
