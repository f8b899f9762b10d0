#!/usr/bin/env bash
# Old target against new, the same seconds each, one after the other, each from an empty corpus
# (plus its seeds), under nice -n 19, the UBSan tree's options of long_run.sh:
#   experiments/fuzz/side_by_side.sh SECONDS TARGET OLD_BINARY OLD_SEEDS OLD_MAX_LEN NEW_BINARY NEW_SEEDS NEW_MAX_LEN
# Prints one TSV line per run: target, variant, seconds, executions, executions/s, user CPU s,
# executions per CPU s, libFuzzer's final cov: and ft:, load average before the run.
set -uo pipefail
s=$1 t=$2; shift 2
export TMPDIR=/dev/shm UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
run() {  # variant binary seeds max_len
  local work; work=$(mktemp -d /dev/shm/sbs-XXXXXX)
  mkdir -p "$work/corpus"
  local load; load=$(cut -d' ' -f1 /proc/loadavg)
  /usr/bin/time -f "%U" -o "$work/cpu" nice -n 19 "$2" -max_total_time="$s" -timeout=30 -rss_limit_mb=2048 \
    -max_len="$4" -print_final_stats=1 "$work/corpus" "$3" > "$work/log" 2>&1 || true
  local execs cpu covft
  execs=$(grep -o 'number_of_executed_units: *[0-9]*' "$work/log" | grep -o '[0-9]*$')
  cpu=$(tail -1 "$work/cpu")
  covft=$(grep -o 'cov: [0-9]* ft: [0-9]*' "$work/log" | tail -1 | awk '{print $2 "\t" $4}')
  printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$t" "$1" "$s" "$execs" "$((execs / s))" "$cpu" \
    "$(awk -v e="$execs" -v c="$cpu" 'BEGIN {printf "%.0f", e / (c > 0 ? c : 1)}')" "$covft" "$load"
  rm -rf "/dev/shm/sbs-corpus-$t-$1"; cp -r "$work/corpus" "/dev/shm/sbs-corpus-$t-$1"; rm -rf "$work"
}
run old "$1" "$2" "$3"
run new "$4" "$5" "$6"
