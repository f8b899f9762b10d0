"""Per (variant, mold, budget): median, IQR, seeds < hand-made (8.0651), median wall s, exact rank-sum p
against the baseline (es_default.yaml, plate.yaml) at the same budget, and against baseline 10k.
Exact two-sided Mann-Whitney by enumeration of the rank-sum distribution with midranks (handles ties).
  python3 analyse.py [results.csv]"""
import csv, statistics, sys
from functools import lru_cache

HAND = 1.7644941278669246 / 1 + 60.25659752737186 / 10 + 274.92100321431417 / 1000  # 8.0651

def q(xs, p):
    xs = sorted(xs); k = (len(xs) - 1) * p; f = int(k); c = min(f + 1, len(xs) - 1)
    return xs[f] + (xs[c] - xs[f]) * (k - f)

def p_exact(a, b):
    """Exact two-sided rank-sum p (midranks; permutation distribution of the sum of a's ranks)."""
    allv = sorted(a + b); n = len(a)
    rank = {}
    i = 0
    while i < len(allv):
        j = i
        while j < len(allv) and allv[j] == allv[i]: j += 1
        rank[allv[i]] = (i + j + 1)  # twice the midrank, integer
        i = j
    r2 = [rank[v] for v in allv]
    # distribution of the sum of n of the doubled ranks
    dist = {(0, 0): 1}
    for r in r2:
        new = dict(dist)
        for (k, s), c in dist.items():
            if k < n: new[(k + 1, s + r)] = new.get((k + 1, s + r), 0) + c
        dist = new
    sums = {s: c for (k, s), c in dist.items() if k == n}
    total = sum(sums.values()); centre = n * (len(allv) + 1)
    obs = sum(rank[v] for v in a)
    return sum(c for s, c in sums.items() if abs(s - centre) >= abs(obs - centre) - 1e-9) / total

rows = list(csv.DictReader(open(sys.argv[1] if len(sys.argv) > 1 else "results.csv")))
groups = {}
for r in rows:
    groups.setdefault((r["variant"], r["mold"], int(r["budget"])), []).append(r)
base = {b: [float(r["objective"]) for r in g] for (v, m, b), g in groups.items() if v == "baseline" and m == "plate.yaml"}
print(f"hand-made layout: {HAND:.4f}")
print(f"{'variant':<22}{'mold':<16}{'budget':>7}{'n':>3}{'median':>9}{'IQR':>17}{'<hand':>7}{'feas':>5}{'circ med':>9}{'wall s':>7}{'es s':>6}{'p vs base@b':>12}{'p vs base10k':>13}")
for (v, m, b), g in groups.items():
    x = [float(r["objective"]) for r in g]
    pb = f"{p_exact(x, base[b]):.3g}" if b in base and v != "baseline" else "-"
    p10 = f"{p_exact(x, base[10000]):.3g}" if not (v == "baseline" and b == 10000) else "-"
    print(f"{v:<22}{m:<16}{b:>7}{len(x):>3}{statistics.median(x):>9.3f}  {q(x,.25):>6.3f}-{q(x,.75):<6.3f}"
          f"{sum(o < HAND for o in x):>6}/{len(x)}{sum(int(r['feasible']) for r in g):>4}"
          f"{statistics.median(int(r['circuits']) for r in g):>9}{statistics.median(float(r['wall_seconds']) for r in g):>7.1f}"
          f"{statistics.median(float(r['es_seconds']) for r in g):>6.1f}{pb:>12}{p10:>13}")
