#!/usr/bin/env bash
# The long round of issue 15 item 3: every target in turn, one at a time, under nice -n 19,
# each for its share of the seconds left until a deadline (UTC, HH:MM), with the same libFuzzer
# options as scripts/fuzz.sh. A crash ends that target's turn (the artifact stays in
# build-fuzz/artifacts/<target>/) and the round goes on with the next target.
#   experiments/fuzz/long_run.sh HH:MM target:weight...
# Needs the fuzz tree built (bash scripts/fuzz.sh 1 builds it). Writes build-fuzz/long_<target>.log
# and one line per target to build-fuzz/long_round.tsv: target, seconds, executions, exit code.
# FUZZ_TREE=build-fuzz-ub runs the UBSan-only tree (cmake -DMTCS_FUZZ_SANITIZERS=undefined, about
# 1.9x the executions/s; no memory errors found there: ASan rounds remain for those); the corpus
# (build-fuzz/corpus/<target>) is shared by both trees.
set -uo pipefail
cd "$(dirname "$0")/../.."
deadline=$(date -u -d "$1" +%s); shift
if [ -z "${TMPDIR:-}" ] && [ -d /dev/shm ] && [ -w /dev/shm ]; then export TMPDIR=/dev/shm; fi
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}"
total=0; for tw in "$@"; do total=$((total + ${tw#*:})); done
left_weight=$total
for tw in "$@"; do
  t=${tw%%:*} w=${tw#*:}
  now=$(date -u +%s)
  seconds=$(( (deadline - now) * w / left_weight ))
  left_weight=$((left_weight - w))
  [ "$seconds" -ge 10 ] || continue
  corpus="build-fuzz/corpus/$t" artifacts="build-fuzz/artifacts/$t"
  mkdir -p "$corpus" "$artifacts"
  max_len=$(awk -v t="$t" '$1 == t {print $2}' fuzz/max_len.tsv)
  start=$(date -u +%s)
  nice -n 19 "${FUZZ_TREE:-build-fuzz}"/fuzz/fuzz_"$t" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
    -max_len="${max_len:-65536}" -print_final_stats=1 -artifact_prefix="$artifacts/" \
    "$corpus" "fuzz/corpus/$t" > "build-fuzz/long_$t.log" 2>&1
  code=$?
  execs=$(grep -o 'number_of_executed_units: *[0-9]*' "build-fuzz/long_$t.log" | grep -o '[0-9]*$')
  printf '%s\t%s\t%s\t%s\t%s\n' "$t" "$(( $(date -u +%s) - start ))" "${execs:-?}" "$code" "${FUZZ_TREE:-build-fuzz}" >> build-fuzz/long_round.tsv
done
