"""Medians per arm of baffles_cup.csv and the exact two-sided rank-sum p of each column."""
import csv
import statistics
import sys
from itertools import combinations


def rank_sum_p(a, b):
    """Exact two-sided Mann-Whitney p by enumeration over the pooled mid-ranks."""
    pooled = sorted(a + b)
    rank = {}
    for v in set(pooled):
        idx = [i + 1 for i, x in enumerate(pooled) if x == v]
        rank[v] = sum(idx) / len(idx)
    ranks = [rank[v] for v in pooled]
    observed = sum(rank[v] for v in a)
    mean = len(a) * (len(pooled) + 1) / 2
    count = total = 0
    for combo in combinations(range(len(pooled)), len(a)):
        total += 1
        if abs(sum(ranks[i] for i in combo) - mean) >= abs(observed - mean) - 1e-9:
            count += 1
    return count / total


rows = list(csv.DictReader(open(sys.argv[1])))
arms = {arm: [r for r in rows if r["arm"] == arm] for arm in ("with", "without")}
print("| | with baffles, median | without, median | rank-sum p (%d + %d) |" % (len(arms["with"]), len(arms["without"])))
print("|---|---:|---:|---:|")
for key in ("core_mean_C", "cycle_s", "mean_C", "std_K", "max_C", "objective", "blind_bores"):
    a = [float(r[key]) for r in arms["with"]]
    b = [float(r[key]) for r in arms["without"]]
    print(f"| {key} | {statistics.median(a):.4g} | {statistics.median(b):.4g} | {rank_sum_p(a, b):.3g} |")
for arm, rs in arms.items():
    print(f"{arm}: feasible {sum(r['feasible'] == 'true' for r in rs)} of {len(rs)}, "
          f"ejectable {sum(r['ejectable'] == 'true' for r in rs)} of {len(rs)}")
