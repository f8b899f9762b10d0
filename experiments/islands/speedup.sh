#!/usr/bin/env bash
# The islands' speed-up on this machine in one command: P = 1 and 2 MPI ranks (and 4: set
# PS="1 2 4"), and the same archipelagos in threads, REPS runs each (best kept), the ES on
# molds/cup.yaml, EVALS evaluations per island. Prints one CSV row per run, then the ratios of
# evaluations/s against P = 1: measured (best wall) and "idle" (a load-independent estimate from
# each rank's CPU seconds per generation, experiments/islands/speedup.py), with the load.
# MODES="mpi threads serial": serial runs the same P islands in one thread, so the very same
# evaluations as P ranks: its ratio is the speed-up of the same work (P islands' layouts cost
# more to evaluate than one island's: speedup.py prints both).
# Mode lockstep: MPI ranks with --migration-delay 0 (the ranks meet at every migration, as before
# the delay existed), lockserial: its islands in one thread; mode mpi: the binary's default delay
# (1 since 2026-11-25), or DELAY=d. The delay changes the run (other migrations, other layouts to
# evaluate): compare each mode with its own serial (speedup.py pairs them).
#   experiments/islands/speedup.sh            # build/mtcs, REPS=3, EVALS=12000, PS="1 2"
#   MODES="mpi serial lockstep lockserial" EVALS=60000 REPS=2 experiments/islands/speedup.sh
set -euo pipefail
cd "$(dirname "$0")/../.."
MTCS=${MTCS:-build/mtcs}
MOLD=${MOLD:-molds/cup.yaml}
REPS=${REPS:-3}
EVALS=${EVALS:-12000}
PS=${PS:-1 2}
MODES=${MODES:-mpi threads}
MPIRUN=${MPIRUN:-mpirun --allow-run-as-root --oversubscribe}
DELAY=${DELAY:-}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
echo "uptime before: $(uptime)" >&2
for rep in $(seq 1 "$REPS"); do
  for P in $PS; do
    for mode in $MODES; do
      run=$out/$mode-$P-$rep
      args="optimize $MOLD --islands $P --seed 1 --evaluations $((EVALS * P)) --migration-every 5 --verbose --out $run"
      [ -n "$DELAY" ] && args="$args --migration-delay $DELAY"
      if [ "$mode" = mpi ]; then cmd="$MPIRUN -np $P $MTCS $args --threads 1"
      elif [ "$mode" = lockstep ]; then cmd="$MPIRUN -np $P $MTCS $args --threads 1 --migration-delay 0"
      elif [ "$mode" = lockserial ]; then cmd="$MTCS $args --threads 1 --migration-delay 0"
      elif [ "$mode" = serial ]; then cmd="$MTCS $args --threads 1"  # the same islands, one thread
      else cmd="$MTCS $args --threads $P"; fi
      cut -d' ' -f1 /proc/loadavg >"$run.load"
      MTCS_ISLANDS_WORK_FILE=$run.work /usr/bin/time -o "$run.time" -f "%U %S" $cmd >/dev/null 2>"$run.err"
    done
  done
done
echo "uptime after: $(uptime)" >&2
python3 experiments/islands/speedup.py "$out" "$(nproc)"
