#!/usr/bin/env bash
# Evaluations/s of the island model on this machine: P = 1, 2, 4 MPI ranks (one island each,
# one thread each), and the same archipelago in threads of one process. The ES on molds/cup.yaml
# (mesh cavity, wall-distance objectives), 3000 evaluations per island. Wall time is the run's
# own (summary.json "seconds": the search loop, store writes included); CPU time is user + sys of
# the whole command (/usr/bin/time, children included). Prints CSV.
set -euo pipefail
cd "$(dirname "$0")/../.."
MTCS=${MTCS:-build/mtcs}
MOLD=molds/cup.yaml
REPS=${REPS:-3}
out=$(mktemp -d)
echo "mode,P,rep,evaluations,run_seconds,evals_per_s,cpu_seconds,evals_per_cpu_s,load1"
for P in 1 2 4; do
  for rep in $(seq 1 "$REPS"); do
    for mode in mpi threads; do
      dir=$out/$mode-$P-$rep
      args="optimize $MOLD --islands $P --seed 1 --evaluations $((3000 * P)) --migration-every 5 --out $dir"
      if [ "$mode" = mpi ]; then
        cmd="mpirun --allow-run-as-root --oversubscribe -np $P $MTCS $args --threads 1"
      else
        cmd="$MTCS $args --threads $P"
      fi
      load=$(cut -d' ' -f1 /proc/loadavg)
      /usr/bin/time -o "$out/time" -f "%U %S" $cmd >/dev/null 2>&1
      cpu=$(awk '{print $1 + $2}' "$out/time")
      python3 - "$dir/summary.json" "$mode" "$P" "$rep" "$cpu" "$load" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
e, t, cpu = s["evaluations"], s["seconds"], float(sys.argv[5])
print(f"{sys.argv[2]},{sys.argv[3]},{sys.argv[4]},{e},{t:.4f},{e / t:.0f},{cpu:.2f},{e / cpu:.0f},{sys.argv[6]}")
PY
    done
  done
done
rm -rf "$out"
