"""plate_samples_quality.sh's CSV: per seed the re-scored weighted objective (std / 1 + max / 10
+ cost / 1000, molds/plate.yaml's scales) of the old and the new spec's best layout; wins, medians.

  python3 experiments/thermal/plate_samples_quality.py OUT.csv
"""
import csv
import sys

rows = list(csv.DictReader(open(sys.argv[1])))
f = lambda r: float(r["temperature_std"]) + float(r["temperature_max"]) / 10 + float(r["cost"]) / 1000
by = {(r["spec"], r["seed"]): r for r in rows}
seeds = sorted({r["seed"] for r in rows}, key=int)
print("seed,old,new,old_std,new_std,old_max,new_max,old_cost,new_cost,old_user_s,new_user_s")
for s in seeds:
    o, n = by[("old", s)], by[("new", s)]
    print(f"{s},{f(o):.3f},{f(n):.3f},{float(o['temperature_std']):.3f},{float(n['temperature_std']):.3f},"
          f"{float(o['temperature_max']):.2f},{float(n['temperature_max']):.2f},{float(o['cost']):.1f},"
          f"{float(n['cost']):.1f},{o['user_s']},{n['user_s']}")
old, new = [f(by[("old", s)]) for s in seeds], [f(by[("new", s)]) for s in seeds]
med = lambda v: sorted(v)[len(v) // 2]
feasible = all(r["feasible"] == "true" for r in rows)
print(f"seeds {len(seeds)}: new better on {sum(n < o for o, n in zip(old, new))}, median old {med(old):.3f} new {med(new):.3f}, "
      f"mean old {sum(old) / len(old):.3f} new {sum(new) / len(new):.3f}, all feasible: {feasible}; "
      f"CPU old {sum(float(by[('old', s)]['user_s']) for s in seeds):.1f} s, new {sum(float(by[('new', s)]['user_s']) for s in seeds):.1f} s")
