#!/usr/bin/env bash
# CPU per ES child on the plate, old binary against new at each thermal.sample_spacing, runs
# alternating: CPU per child = (user at N = 1000 - user at N = 300) / 700 / SEEDS (default 1; the
# ES's path, and with it its children, differs per spacing: more seeds average that out).
#   bash experiments/thermal/plate_samples_time.sh OLD_BENCH NEW_BENCH OUT.csv [ROUNDS] [SPACINGS]
# The mold variants are PLATE with `sample_spacing: S` added to its thermal section
# (written to $TMPDIR); "-" in SPACINGS runs the old binary on PLATE as is.
set -euo pipefail
old=$1 new=$2 out=$3 rounds=${4:-3} spacings=${5:-"- 5.5 8 11 16.5"}
tmp=$(mktemp -d)
# The base spec: main's molds/plate.yaml (no thermal.sample_spacing), e.g.
# git show 3cca68c:molds/plate.yaml > /tmp/plate_old.yaml; PLATE=/tmp/plate_old.yaml bash ...
plate=${PLATE:-molds/plate.yaml}
grep -q "^  sample_spacing: .*" <(sed -n '/^thermal:/,$p' "$plate") && { echo "PLATE must not set thermal.sample_spacing" >&2; exit 2; }
echo "round,binary,spacing,seeds,evaluations,user_s,load1" > "$out"
for r in $(seq "$rounds"); do
  for s in $spacings; do
    bin=$new mold=$plate
    if [ "$s" = "-" ]; then bin=$old; else
      mold=$tmp/plate_$s.yaml
      sed "s/^  tier: t2d$/  tier: t2d\n  sample_spacing: $s/" "$plate" > "$mold"
    fi
    for n in 300 1000; do
      u=$( { /usr/bin/time -f %U nice -n 5 "$bin" optimize "$mold" --algorithm es --seeds "${SEEDS:-1}" --evaluations "$n" >/dev/null; } 2>&1 | tail -1)
      echo "$r,$([ "$s" = "-" ] && echo old || echo new),${s/-/cavity},${SEEDS:-1},$n,$u,$(cut -d' ' -f1 /proc/loadavg)" | tee -a "$out"
    done
  done
done
rm -rf "$tmp"
