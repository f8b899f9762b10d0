#!/usr/bin/env bash
# The library as others use it: cmake --install into a scratch prefix, then a small program of
# its own (tests/install/consumer) configured with find_package(mtcs) against that prefix alone,
# built and run; its evaluation of a layout must equal the installed `mtcs evaluate` bit for bit.
# Usage: consumer_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$1 source=$2
prefix=$(realpath "$(mktemp -d)")
trap 'rm -rf "$prefix"' EXIT
cmake --install "$build" --prefix "$prefix" >/dev/null
[[ -e "$prefix/include/mtcs/run/session.h" && ! -e "$prefix/include/mtcs/cli" ]] || { echo "headers not installed as expected"; exit 1; }
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
# A sanitizer build's libraries need the sanitizers' runtime in the program too.
if grep -q '^MTCS_SANITIZE:BOOL=ON' "$build/CMakeCache.txt"; then
  launcher+=(-DCMAKE_CXX_FLAGS=-fsanitize=address,undefined -DCMAKE_EXE_LINKER_FLAGS=-fsanitize=address,undefined)
fi
cmake -S "$source/tests/install/consumer" -B "$prefix/consumer-build" -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_PREFIX_PATH="$prefix" "${launcher[@]}" >/dev/null
cmake --build "$prefix/consumer-build" -j2 >/dev/null
cd "$prefix"
got=$("$prefix/consumer-build/consumer" "$source/molds/plate.yaml" "$source/molds/plate.layout.yaml")
want=$("$prefix/bin/mtcs" evaluate "$source/molds/plate.yaml" --layout "$source/molds/plate.layout.yaml" --json |
       python3 -c 'import json, sys; j = json.load(sys.stdin); print("feasible", int(j["feasible"])); [print(repr(v)) for v in j["objectives"].values()]')
python3 - "$got" "$want" <<'PY'
import sys
# The library's progress lines (spdlog's default logger writes to stdout) are not the result.
got = [line for line in sys.argv[1].split("\n") if not line.startswith("[")]
want = sys.argv[2].split("\n")
same = len(got) == len(want) and got[0] == want[0] and all(float(a) == float(b) for a, b in zip(got[1:], want[1:]))
if not same:
    print("the program built against the installed library disagrees with mtcs evaluate:\n", got, "\n", want)
    sys.exit(1)
PY
echo "a program built against the installed mtcs library in $prefix evaluates as mtcs does"
