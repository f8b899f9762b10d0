"""Median best objective per binary and mold, and the two-sided Mann-Whitney rank-sum test
(normal approximation with ties), from es_quality.sh's CSV."""
import csv
import math
import statistics
import sys

rows = list(csv.DictReader(open(sys.argv[1])))
for mold in sorted({r["mold"] for r in rows}):
    a = [float(r["best_objective"]) for r in rows if r["mold"] == mold and r["binary"] == "old"]
    b = [float(r["best_objective"]) for r in rows if r["mold"] == mold and r["binary"] == "new"]
    u = sum((x < y) + 0.5 * (x == y) for x in a for y in b)  # pairs in which old is lower (better)
    n, m = len(a), len(b)
    mean, sd = n * m / 2, math.sqrt(n * m * (n + m + 1) / 12)
    z = (abs(u - mean) - 0.5) / sd if u != mean else 0.0
    p = math.erfc(z / math.sqrt(2))
    same = sum(x == y for x, y in zip(a, b))
    print(f"{mold}: old median {statistics.median(a):.6g}, new median {statistics.median(b):.6g}, "
          f"U(old lower) = {u} of {n * m}, p = {p:.2f}, equal in {same} of {n} seeds")
