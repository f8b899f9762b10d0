#!/usr/bin/env bash
# cmake --install into a scratch prefix, then the installed binaries as a user runs them, away
# from the checkout and the build tree: mtcs evaluates a mold, `mtcs bench` finds the installed
# mtcs-bench, and the plotting scripts sit in PREFIX/share/mtcs where mtcs looks for them.
# Usage: install_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$1 source=$2
prefix=$(realpath "$(mktemp -d)")
trap 'rm -rf "$prefix"' EXIT
cmake --install "$build" --prefix "$prefix" >/dev/null
for f in bin/mtcs bin/mtcs-bench share/mtcs/plot_fronts.py share/mtcs/plot_penalties.py; do
  [[ -e "$prefix/$f" ]] || { echo "not installed: $f"; exit 1; }
done
cp "$source/molds/plate.yaml" "$source/molds/plate.layout.yaml" "$prefix/"
cd "$prefix"
# Whole outputs first: grep -q would close the pipe early and, under pipefail, fail a long writer.
scored=$("$prefix/bin/mtcs" evaluate plate.yaml --layout plate.layout.yaml --json)
grep -q '"feasible"' <<<"$scored"
bench=$("$prefix/bin/mtcs" bench sms-emoa --problem zdt1 --seeds 1 --evaluations 200 --algorithms nsga2)
grep -q '^zdt1,nsga2,1,200,' <<<"$bench"
# The plotting script is the installed one: it renders the PNG, or (without matplotlib) the
# hint to render it later names it.
log=$("$prefix/bin/mtcs" compare-penalties plate.yaml --variants death --seeds 1 --evaluations 60 --out cmp 2>&1)
if [[ ! -e cmp/penalties.png ]] && ! grep -q "$prefix/share/mtcs/plot_penalties.py" <<<"$log"; then
  echo "the installed plotting script was not used:"; echo "$log"; exit 1
fi
echo "installed mtcs and mtcs-bench run from $prefix"
