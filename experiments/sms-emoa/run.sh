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
print("| problem | SMS-EMOA | NSGA-II | MOEA/D | seeds (SMS) | s per SMS run |")
print("|---|---:|---:|---:|---:|---:|")
for p in sorted({r["problem"] for r in rows}, key=lambda s: (s[:3], int(s[-1]))):
    med = {}
    for a in ("sms-emoa", "nsga2", "moead"):
        v = [float(r["hypervolume"]) for r in rows if r["problem"] == p and r["algorithm"] == a]
        med[a] = statistics.median(v) if v else float("nan")
    sms = [r for r in rows if r["problem"] == p and r["algorithm"] == "sms-emoa"]
    secs = statistics.median(float(r["seconds"]) for r in sms)
    print(f"| {p} | {med['sms-emoa']:.4f} | {med['nsga2']:.4f} | {med['moead']:.4f} | {len(sms)} | {secs:.1f} |")
PY
