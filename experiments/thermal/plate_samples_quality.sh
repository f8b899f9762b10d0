#!/usr/bin/env bash
# Does the ES find layouts as good with the coarse samples? The demo's run (configs/es_default.yaml,
# 10 000 evaluations) for seeds 1..K on the old plate.yaml (cavity samples) and on the new one
# (thermal.sample_spacing: 11), one thread; each best layout re-scored on the old plate.yaml (the
# 1 166 samples), CSV: spec,seed,user_s,temperature_std,temperature_max,cost (re-scored).
#   bash experiments/thermal/plate_samples_quality.sh MTCS OLD_PLATE.yaml OUT.csv [K]   (FIRST=7: seeds 7..K, appended)
set -euo pipefail
mtcs=$1 old_plate=$2 out=$3 k=${4:-8}
tmp=$(mktemp -d)
[ -n "${FIRST:-}" ] || echo "spec,seed,user_s,feasible,temperature_std,temperature_max,cost" > "$out"
for s in $(seq "${FIRST:-1}" "$k"); do
  for spec in old new; do
    mold=$([ $spec = old ] && echo "$old_plate" || echo molds/plate.yaml)
    /usr/bin/time -o "$tmp/user" -f %U nice -n 5 "$mtcs" optimize "$mold" --config configs/es_default.yaml \
      --evaluations 10000 --seed "$s" --threads 1 --quiet --out "$tmp/$spec$s" >/dev/null 2>&1
    j=$("$mtcs" evaluate "$old_plate" --layout "$tmp/$spec$s/best.layout.yaml" --json)
    echo "$spec,$s,$(tail -1 "$tmp/user"),$(echo "$j" | python3 -c 'import json,sys; j=json.load(sys.stdin); o=j["objectives"]; print(",".join([str(j["feasible"]).lower()] + [str(o[k]) for k in ("temperature_std","temperature_max","cost")]))')" | tee -a "$out"
  done
done
rm -rf "$tmp"
