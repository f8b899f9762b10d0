"""plate_samples.cpp's CSV: per sample spacing and layout set, the errors of the coarse
objectives against the cavity's samples (same tier) and Kendall tau of the std (against the
full-sample std and, where the CSV has fd rows, against T3).

  python3 experiments/thermal/plate_samples.py samples.csv
"""
import csv
import sys
from collections import defaultdict

sys.path.insert(0, __import__("os").path.dirname(__import__("os").path.abspath(__file__)))
from plate_diagnosis import kendall  # noqa: E402

rows = list(csv.DictReader(open(sys.argv[1])))
line = {(r["tier"], float(r["spacing"]), r["set"], r["layout"]): r for r in rows}
line_sinks = sorted({r["tier"] for r in rows if not r["tier"].startswith("fd")})
spacings = sorted({float(r["spacing"]) for r in rows if r["tier"] in line_sinks})
full = spacings[0]
groups = {"random": lambda s: s.startswith("random"), "ES results": lambda s: s.startswith("es:"),
          "all": lambda s: True}
fd = [r for r in rows if r["tier"].startswith("fd")]


def stat(v):
    v = sorted(v)
    return max(v), v[len(v) // 2]


print("tier,layouts,spacing,samples,max_abs_d_std_k,median_abs_d_std_k,max_abs_d_mean_k,median_abs_d_mean_k,"
      "max_under_read_max_k,median_under_read_max_k,max_over_read_max_k,rel_d_std_max,tau_std_vs_full,ms_median")
for tier in line_sinks:
    for label, keep in groups.items():
        keys = sorted({(r["set"], r["layout"]) for r in rows if r["tier"] == tier and keep(r["set"])})
        for s in spacings:
            ref = [line[(tier, full, *k)] for k in keys]
            new = [line[(tier, s, *k)] for k in keys]
            d = lambda f: [float(b[f]) - float(a[f]) for a, b in zip(ref, new)]
            ds, dm, dx = d("std"), d("mean"), d("max")
            rel = max(abs(x) / float(a["std"]) for x, a in zip(ds, ref))
            tau = kendall([float(a["std"]) for a in ref], [float(b["std"]) for b in new])
            ms = sorted(float(b["ms"]) for b in new)[len(new) // 2]
            print(f"{tier},{label},{s:g},{new[0]['samples']},{stat(map(abs, ds))[0]:.4f},{stat(map(abs, ds))[1]:.4f},"
                  f"{stat(map(abs, dm))[0]:.4f},{stat(map(abs, dm))[1]:.4f},{stat([-x for x in dx])[0]:.3f},"
                  f"{stat([-x for x in dx])[1]:.3f},{max(dx):.3f},{rel:.4f},{tau:.4f},{ms:.2f}")
if fd:
    print("\ntier,t3,layouts,count,spacing,tau_std_vs_t3")
    for label, keep in groups.items():
        sel = [r for r in fd if keep(r["set"])]
        keys = [(r["set"], r["layout"]) for r in sel]
        t3 = [float(r["std"]) for r in sel]
        for tier in line_sinks:
            for s in spacings:
                tau = kendall([float(line[(tier, s, *k)]["std"]) for k in keys], t3)
                print(f"{tier},{sel[0]['tier']},{label},{len(keys)},{s:g},{tau:.4f}")
