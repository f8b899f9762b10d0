#!/usr/bin/env bash
# Builds with AddressSanitizer + UBSan into build-asan/ and runs every case of the modules below
# the commands, and of the others (whose cases run whole pipelines or the mtcs binary, minutes
# under ASan) those that read user input or stress a kernel.
set -euo pipefail
cd "$(dirname "$0")/.."
# Paths relative to the checkout in ccache's hashes: clones and worktrees share the cache.
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$PWD}"
# Debug builds (-g) hash the working folder too unless told not to: clones would never hit.
export CCACHE_NOHASHDIR="${CCACHE_NOHASHDIR:-1}"
# Ninja for a new tree, as scripts/build.sh.
if command -v ninja >/dev/null 2>&1; then export CMAKE_GENERATOR="${CMAKE_GENERATOR:-Ninja}"; fi
# -O1 and line tables only (what OSS-Fuzz builds with): stack traces keep file:line, and a cold
# build takes ~2.5x less than -O2 -g (experiments/ci/README.md). clang++-14 (scripts/setup.sh
# installs it for the fuzzers) compiles the tree in 0.67x gcc's time; MTCS_ASAN_CXX=c++ builds
# it with gcc (experiments/ci/README.md, "The sanitizer tree with clang").
CXX_ASAN="$(command -v "${MTCS_ASAN_CXX:-clang++-14}" || command -v c++)"
# A tree configured with another compiler cannot switch: it starts over.
if [ -f build-asan/CMakeCache.txt ] && ! grep -qx "CMAKE_CXX_COMPILER:[A-Z]*=$CXX_ASAN" build-asan/CMakeCache.txt; then
  rm -rf build-asan
fi
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER="$CXX_ASAN" \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DMTCS_SANITIZE=ON -DMTCS_BUILD_TESTS=ON -DMTCS_BUILD_BENCH=ON >/dev/null
cmake --build build-asan -j2
# OpenCASCADE's libraries (the STEP export) keep allocations for the process's life: suppressed.
export ASAN_OPTIONS=detect_leaks=1 LSAN_OPTIONS="suppressions=$PWD/scripts/lsan_suppressions.txt" \
  UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
# Which cases: scripts/sanitize_selection.sh (the claims ledger counts them from there too).
source scripts/sanitize_selection.sh
# --no-tests=error: a selection that matches nothing is a broken selection, not a pass.
ctest --test-dir build-asan --output-on-failure --no-tests=error -j2 -L "$modules" -E "$slow"
ctest --test-dir build-asan --output-on-failure --no-tests=error -j2 -LE "$modules" -E "$heavy"
# Coverage-guided fuzzing of every reader, a few seconds a target (skipped without clang/libFuzzer).
if [ "${MTCS_SKIP_FUZZ:-0}" != 1 ]; then bash scripts/fuzz.sh --smoke; fi
