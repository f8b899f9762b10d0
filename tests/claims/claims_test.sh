#!/usr/bin/env bash
# The claims ledger's check (scripts/claims.py check): README.md as it stands passes; a copy with a
# figure the ledger lacks, or with a claim's figure changed, fails naming it.
#   claims_test.sh SOURCE_DIR WORK_DIR
set -euo pipefail
src=$1 work=$2
rm -rf "$work" && mkdir -p "$work"
python3 "$src/scripts/claims.py" check
# A new figure nobody measured.
sed 's/^Run the tests:$/Run the tests (42 ms a case):/' "$src/README.md" > "$work/extra.md"
if python3 "$src/scripts/claims.py" check --readme "$work/extra.md" 2> "$work/extra.err"; then
  echo "a README with an unmeasured figure passed" >&2; exit 1
fi
grep -q "42 ms" "$work/extra.err" || { cat "$work/extra.err" >&2; exit 1; }
# A claim's figure edited away from the ledger's.
sed -E 's/[0-9]+× faster than FCL/99× faster than FCL/' "$src/README.md" > "$work/edited.md"
if python3 "$src/scripts/claims.py" check --readme "$work/edited.md" 2> "$work/edited.err"; then
  echo "a README with an edited figure passed" >&2; exit 1
fi
grep -q "fcl-ratio" "$work/edited.err" || { cat "$work/edited.err" >&2; exit 1; }
echo "claims: the check passes README.md and catches an unmeasured and an edited figure"
