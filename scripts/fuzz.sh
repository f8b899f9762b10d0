#!/usr/bin/env bash
# Coverage-guided fuzzing of every reader of user files (libFuzzer, ASan + UBSan), built with
# clang into build-fuzz/ (fuzz/CMakeLists.txt lists the targets).
#   scripts/fuzz.sh [SECONDS] [TARGET...]   long runs: SECONDS per target (default 600), every
#                                           target unless named (mold_spec, mesh_stl, ...)
#   scripts/fuzz.sh --smoke                 the test suite's short run: 7 s a target (about 9 s
#                                           with start and end: under 2 minutes for all 12)
# Seeds come from fuzz/corpus/<target>/ (read only); what a run learns goes to
# build-fuzz/corpus/<target>/, crashes to build-fuzz/artifacts/<target>/ and fail the script.
# Without clang-14 or libFuzzer (libfuzzer-14-dev) it says so and exits 0 (1 under the test
# command, which sets MTCS_FUZZ_REQUIRED=1).
set -euo pipefail
cd "$(dirname "$0")/.."
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$PWD}" CCACHE_NOHASHDIR="${CCACHE_NOHASHDIR:-1}"
# Ninja for a new tree, as scripts/build.sh.
if command -v ninja >/dev/null 2>&1; then export CMAKE_GENERATOR="${CMAKE_GENERATOR:-Ninja}"; fi

CXX_FUZZ="${MTCS_FUZZ_CXX:-clang++-14}"
seconds=600
if [ "${1:-}" = --smoke ]; then seconds="${MTCS_FUZZ_SMOKE_SECONDS:-7}"; shift
elif [[ "${1:-}" =~ ^[0-9]+$ ]]; then seconds="$1"; shift; fi

if ! command -v "$CXX_FUZZ" >/dev/null 2>&1; then
  echo "fuzz: $([ "${MTCS_FUZZ_REQUIRED:-0}" = 1 ] && echo FAILED || echo SKIPPED): $CXX_FUZZ not found (apt-get install clang-14 libfuzzer-14-dev)"
  exit "${MTCS_FUZZ_REQUIRED:-0}"
fi
probe=$(mktemp -d)
trap 'rm -rf "$probe"' EXIT
echo 'extern "C" int LLVMFuzzerTestOneInput(const unsigned char*, unsigned long) { return 0; }' > "$probe/p.cpp"
if ! "$CXX_FUZZ" -fsanitize=fuzzer "$probe/p.cpp" -o "$probe/p" >/dev/null 2>&1; then
  echo "fuzz: $([ "${MTCS_FUZZ_REQUIRED:-0}" = 1 ] && echo FAILED || echo SKIPPED): $CXX_FUZZ cannot link -fsanitize=fuzzer (apt-get install libfuzzer-14-dev)"
  exit "${MTCS_FUZZ_REQUIRED:-0}"
fi

# Each file compiled alone, not in the unity batches of the other trees: a file that uses a
# header only a batch-mate includes fails here. mtcs_cli too, so that every module's files are.
# -O1 and line tables only, as OSS-Fuzz builds: a cold build ~2.5x faster than -O2 -g.
cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER="$CXX_FUZZ" \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only -DNDEBUG" \
  -DMTCS_FUZZ=ON -DMTCS_BUILD_TESTS=OFF -DMTCS_UNITY_BUILD=OFF >/dev/null
cmake --build build-fuzz -j2 --target mtcs_fuzz mtcs_cli

targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(mold_spec layout pairs_csv cylinders_csv points_csv front_file
                                     mesh_stl mesh_off mesh_obj mesh_ply run_store)
# The review server's BCF reader: built when the server's libraries are (fuzz/CMakeLists.txt).
if [ $# -eq 0 ] && [ -x build-fuzz/fuzz/fuzz_bcf ]; then targets+=(bcf); fi
# Every execution writes its input to a file: on tmpfs when there is one.
if [ -z "${TMPDIR:-}" ] && [ -d /dev/shm ] && [ -w /dev/shm ]; then export TMPDIR=/dev/shm; fi
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}"
for t in "${targets[@]}"; do
  corpus="build-fuzz/corpus/$t" artifacts="build-fuzz/artifacts/$t"
  mkdir -p "$corpus" "$artifacts"
  # -rss_limit_mb: a reader that allocates gigabytes for a small file is a finding too.
  max_len=$(awk -v t="$t" '$1 == t {print $2}' fuzz/max_len.tsv)
  if ! build-fuzz/fuzz/fuzz_"$t" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
       -max_len="${max_len:-65536}" -print_final_stats=1 -artifact_prefix="$artifacts/" \
       "$corpus" "fuzz/corpus/$t" > "build-fuzz/fuzz_$t.log" 2>&1; then
    echo "fuzz: $t FAILED: see build-fuzz/fuzz_$t.log and $artifacts/"; tail -40 "build-fuzz/fuzz_$t.log"; exit 1
  fi
  echo "fuzz: $t: $(grep -o 'number_of_executed_units: *[0-9]*' "build-fuzz/fuzz_$t.log" | grep -o '[0-9]*') executions in ${seconds} s, no crash"
done
