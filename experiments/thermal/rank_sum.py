"""Median T3 std per objective and the exact two-sided Mann-Whitney rank-sum test (continuous
values: no ties), from es_physics_vs_distance.csv. With a second CSV: the runs of the first
against those of the second (two settings of the physics arm; each file one arm).
  python3 rank_sum.py STUDY.csv [OTHER.csv]"""
import csv
import statistics
import sys
from functools import lru_cache


@lru_cache(maxsize=None)
def ways(n, m, u):
    """Orderings of n + m distinct values in which U (pairs with the first sample lower) is u."""
    if u < 0:
        return 0
    if n == 0 or m == 0:
        return int(u == 0)
    # The largest value is from the second sample (every first-sample value is below it) or not.
    return ways(n, m - 1, u - n) + ways(n - 1, m, u)


def p_exact(n, m, u):
    """The exact two-sided p of U = u for samples of n and m distinct values."""
    total = sum(ways(n, m, k) for k in range(n * m + 1))
    centre = n * m / 2
    return sum(ways(n, m, k) for k in range(n * m + 1) if abs(k - centre) >= abs(u - centre)) / total


def main():
    rows = list(csv.DictReader(open(sys.argv[1])))
    by = {}
    for r in rows:
        by.setdefault(r["objective"], []).append(float(r["t3_std_k"]))
    names = "physics (temperature_std)", "wall distance (uniformity)"
    if len(sys.argv) > 2:  # one arm per file, whatever its objectives
        a = [float(r["t3_std_k"]) for r in rows]
        b = [float(r["t3_std_k"]) for r in csv.DictReader(open(sys.argv[2]))]
        names = sys.argv[1], sys.argv[2]
    else:
        a, b = by["temperature_std"], by["uniformity"]
    n, m = len(a), len(b)
    u = sum(x < y for x in a for y in b)  # pairs in which the physics run's layout is cooler-even


    p = p_exact(n, m, u)
    whose = "the physics run's" if len(sys.argv) <= 2 else "the first's"
    print(f"T3 patch std, median over {n} seeds: {names[0]} {statistics.median(a):.4f} K, "
          f"{names[1]} {statistics.median(b):.4f} K")
    print(f"U = {u} of {n * m} pairs have {whose} layout more uniform; exact two-sided p = {p:.2e}")
    if "t2d_std_k" in rows[0]:
        # How well the loop's tier ranks the best layouts as the reference does (both arms together).
        solved = [r for r in rows if r["t2d_std_k"]]
        a = [float(r["t2d_std_k"]) for r in solved]
        b = [float(r["t3_std_k"]) for r in solved]
        sign = lambda x: (x > 0) - (x < 0)
        s = sum(sign(a[i] - a[j]) * sign(b[i] - b[j]) for i in range(len(a)) for j in range(i + 1, len(a)))
        print(f"Kendall tau of the T2d std against the T3 std over the {len(a)} best layouts: "
              f"{s / (len(a) * (len(a) - 1) / 2):.3f}")


if __name__ == "__main__":
    main()
