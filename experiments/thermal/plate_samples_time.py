"""CPU per child from plate_samples_time.sh / plate_samples_children.sh CSVs: per binary and
spacing, (user at the larger count - user at the smaller) / the difference / seeds, per round,
their mean and the ratio to the old binary's.

  python3 experiments/thermal/plate_samples_time.py OUT.csv
"""
import csv
import sys
from collections import defaultdict
rows = list(csv.DictReader(open(sys.argv[1])))
lo, hi = sorted({int(r["evaluations"]) for r in rows})
u = defaultdict(dict)
seeds = {}
for r in rows:
    seeds[(r["round"], r["binary"], r["spacing"])] = int(r.get("seeds") or 1)
    u[(r["round"], r["binary"], r["spacing"])][int(r["evaluations"])] = float(r["user_s"])
per = defaultdict(list)
for (rd, b, s), v in u.items():
    if lo in v and hi in v: per[(b, s)].append((v[hi] - v[lo]) / (hi - lo) / seeds[(rd, b, s)] * 1e3)
old = sum(per[("old", "cavity")]) / len(per[("old", "cavity")])
loads = [float(r["load1"]) for r in rows]
print(f"load1 {min(loads):.2f}-{max(loads):.2f}")
print("binary,spacing,rounds,ms_per_child_each,ms_mean,ratio_to_old")
for (b, s), v in sorted(per.items(), key=lambda kv: (kv[0][0] != "old", float(kv[0][1]) if kv[0][1] != "cavity" else 0)):
    m = sum(v) / len(v)
    print(f"{b},{s},{len(v)},{' '.join(f'{x:.3f}' for x in v)},{m:.3f},{m / old:.2f}")
