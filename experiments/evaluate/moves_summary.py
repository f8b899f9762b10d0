"""Medians of the ES's best objective per mold and arm, and the exact two-sided rank-sum p."""
import csv
import statistics
import sys
from itertools import combinations


def rank_sum_p(a, b):
    """Exact two-sided Mann-Whitney p (no ties assumed beyond mid-ranks) by enumeration."""
    pooled = sorted(a + b)
    rank = {}
    for v in set(pooled):
        idx = [i + 1 for i, x in enumerate(pooled) if x == v]
        rank[v] = sum(idx) / len(idx)
    ranks = [rank[v] for v in pooled]
    observed = sum(rank[v] for v in a)
    n = len(a)
    mean = n * (len(pooled) + 1) / 2
    count = total = 0
    for combo in combinations(range(len(pooled)), n):
        s = sum(ranks[i] for i in combo)
        total += 1
        if abs(s - mean) >= abs(observed - mean) - 1e-9:
            count += 1
    return count / total


rows = list(csv.DictReader(open(sys.argv[1])))
for mold in sorted({r["mold"] for r in rows}):
    arms = {}
    for r in rows:
        if r["mold"] == mold:
            arms.setdefault(r["arm"], []).append(float(r["best_objective"]))
    line = [mold]
    for arm, v in sorted(arms.items()):
        line.append(f"{arm}: median {statistics.median(v):.4f} (n={len(v)})")
    if len(arms) == 2:
        a, b = list(arms.values())
        line.append(f"p = {rank_sum_p(a, b):.3g}")
    print("; ".join(line))
