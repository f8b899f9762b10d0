"""Per run: the feasible share of the initial population (200 sampled layouts, generation 0 of
the init runs; and the 10 of the ES runs), the final best weighted objective (the ES's
best_objective, feasible runs only), the wall time. Per mold: medians and the exact two-sided
Mann-Whitney rank-sum test, guided vs unguided (ties counted half)."""
import csv
import json
import os
import sqlite3
import statistics
import sys
from functools import lru_cache

runs, csv_out = sys.argv[1], sys.argv[2]


def gen0_share(d):
    c = sqlite3.connect(os.path.join(d, "run.sqlite"))
    return c.execute("select feasible_share from generation where idx = 0").fetchone()[0]


rows = []
for name in sorted(os.listdir(runs)):
    mold, kind, arm, seed = name.rsplit("_", 3)
    if kind != "es":
        continue
    d = os.path.join(runs, name)
    s = json.load(open(os.path.join(d, "summary.json")))
    rows.append({"mold": mold, "guided": arm, "seed": int(seed),
                 "init_feasible_share_200": gen0_share(os.path.join(runs, f"{mold}_init_{arm}_{seed}")),
                 "init_feasible_share_es10": gen0_share(d),
                 "final_objective": s["best_objective"], "final_feasible": s["feasible"],
                 "evaluations": s["evaluations"], "seconds": round(s["seconds"], 3)})
rows.sort(key=lambda r: (r["mold"], r["guided"], r["seed"]))
with open(csv_out, "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=list(rows[0]))
    w.writeheader()
    w.writerows(rows)


@lru_cache(maxsize=None)
def ways(n, m, u2):
    """Orderings of n + m distinct values in which 2U is u2 (no ties: the exact null)."""
    if u2 < 0:
        return 0
    if n == 0 or m == 0:
        return int(u2 == 0)
    return ways(n, m - 1, u2 - 2 * n) + ways(n - 1, m, u2)


def rank_sum_p(a, b):
    """Two-sided exact p of U = #(a < b) + #(a == b)/2 (the null without ties)."""
    n, m = len(a), len(b)
    u2 = sum(2 * (x < y) + (x == y) for x in a for y in b)
    total = sum(ways(n, m, k) for k in range(0, 2 * n * m + 1, 2))
    centre = n * m
    return sum(ways(n, m, k) for k in range(0, 2 * n * m + 1, 2) if abs(k - centre) >= abs(u2 - centre)) / total


print("| mold | metric | guided median | unguided median | rank-sum p (two-sided) |")
print("|---|---|---|---|---|")
for mold in sorted({r["mold"] for r in rows}):
    on = [r for r in rows if r["mold"] == mold and r["guided"] == "on"]
    off = [r for r in rows if r["mold"] == mold and r["guided"] == "off"]
    for key in ["init_feasible_share_200", "init_feasible_share_es10", "final_objective", "seconds"]:
        a, b = [r[key] for r in on], [r[key] for r in off]
        print(f"| {mold} | {key} | {statistics.median(a):.4g} | {statistics.median(b):.4g} | {rank_sum_p(a, b):.3g} |")
    fa = sum(r["final_feasible"] for r in on)
    fb = sum(r["final_feasible"] for r in off)
    print(f"| {mold} | final best feasible (runs) | {fa}/{len(on)} | {fb}/{len(off)} | |")
