#!/usr/bin/env bash
# A long round by executions instead of seconds: each target in turn until it has run its given
# number of executions (libFuzzer's -runs) or a deadline (UTC, HH:MM) comes, under nice -n 19,
# with the same options as long_run.sh. For topping up the targets short of 10 M:
#   FUZZ_TREE=build-fuzz-ub experiments/fuzz/count_run.sh 17:00 run_store:150000 layout:6000000
# Writes build-fuzz/long_<target>_<pid>.log and a line per target to build-fuzz/long_round.tsv (target,
# seconds, executions, exit code, tree), as long_run.sh does. Do not start it with setsid: in an
# autogroup of its own nice 19 no longer yields to other sessions.
set -uo pipefail
cd "$(dirname "$0")/../.."
deadline=$(date -u -d "$1" +%s); shift
if [ -z "${TMPDIR:-}" ] && [ -d /dev/shm ] && [ -w /dev/shm ]; then export TMPDIR=/dev/shm; fi
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}"
for tr in "$@"; do
  t=${tr%%:*} runs=${tr#*:}
  seconds=$(( deadline - $(date -u +%s) ))
  [ "$seconds" -ge 10 ] || break
  corpus="build-fuzz/corpus/$t" artifacts="build-fuzz/artifacts/$t"
  mkdir -p "$corpus" "$artifacts"
  max_len=$(awk -v t="$t" '$1 == t {print $2}' fuzz/max_len.tsv)
  start=$(date -u +%s)
  nice -n 19 "${FUZZ_TREE:-build-fuzz}"/fuzz/fuzz_"$t" -runs="$runs" -max_total_time="$seconds" -timeout=10 \
    -rss_limit_mb=2048 -max_len="${max_len:-65536}" -print_final_stats=1 -artifact_prefix="$artifacts/" \
    "$corpus" "fuzz/corpus/$t" > "build-fuzz/long_${t}_$$.log" 2>&1
  code=$?
  execs=$(grep -o 'number_of_executed_units: *[0-9]*' "build-fuzz/long_${t}_$$.log" | grep -o '[0-9]*$')
  printf '%s\t%s\t%s\t%s\t%s\n' "$t" "$(( $(date -u +%s) - start ))" "${execs:-?}" "$code" "${FUZZ_TREE:-build-fuzz}" >> build-fuzz/long_round.tsv
done
