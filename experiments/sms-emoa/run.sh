#!/usr/bin/env bash
# SMS-EMOA against pagmo's NSGA-II and MOEA/D: ZDT1-4, ZDT6 with 20 000 evaluations and DTLZ1-7
# (3 objectives) with 30 000, 11 seeds each. Usage: bash experiments/sms-emoa/run.sh (after a
# build; about 10 minutes)
set -euo pipefail
cd "$(dirname "$0")/../.."
out=experiments/sms-emoa/results.csv
echo "problem,algorithm,seed,evaluations,hypervolume,seconds" > "$out"
for p in zdt1 zdt2 zdt3 zdt4 zdt6; do
  ./build/mtcs bench sms-emoa --problem $p --seeds 11 --evaluations 20000 | tail -n +2 >> "$out"
done
for p in dtlz1 dtlz2 dtlz3 dtlz4 dtlz5 dtlz6 dtlz7; do
  ./build/mtcs bench sms-emoa --problem $p --seeds 11 --evaluations 30000 | tail -n +2 >> "$out"
done
/usr/bin/python3 - "$out" <<'PY'
import csv, statistics, sys
rows = list(csv.DictReader(open(sys.argv[1])))
print("| problem | SMS-EMOA | NSGA-II | MOEA/D | s/run SMS-EMOA | s/run NSGA-II | s/run MOEA/D |")
print("|---|---:|---:|---:|---:|---:|---:|")
for p in sorted({r["problem"] for r in rows}, key=lambda s: (s[:3], int(s[-1]))):
    med, secs = {}, {}
    for a in ("sms-emoa", "nsga2", "moead"):
        runs = [r for r in rows if r["problem"] == p and r["algorithm"] == a]
        med[a] = statistics.median(float(r["hypervolume"]) for r in runs) if runs else float("nan")
        secs[a] = statistics.median(float(r["seconds"]) for r in runs) if runs else float("nan")
    print(f"| {p} | {med['sms-emoa']:.4f} | {med['nsga2']:.4f} | {med['moead']:.4f} | "
          f"{secs['sms-emoa']:.2f} | {secs['nsga2']:.2f} | {secs['moead']:.2f} |")
PY
