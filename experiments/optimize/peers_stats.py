"""What the peer comparisons under experiments/optimize/ share: a results CSV of `mtcs-bench optimize`
per algorithm, quartiles, and the two-sided rank-sum p (Mann-Whitney U, scipy)."""
import csv
import math
import os
import statistics

from scipy.stats import mannwhitneyu


def results(path, column="best_objective"):
    """{algorithm: [values]} of one results CSV ({} if it is missing). The best objective of a run
    without a feasible layout counts as inf."""
    out = {}
    if not os.path.exists(path):
        return out
    with open(path) as f:
        for r in csv.DictReader(f):
            v = float(r[column])
            if column == "best_objective" and r["feasible"] != "1":
                v = math.inf
            out.setdefault(r["algorithm"], []).append(v)
    return out


def quartiles(v):
    q = statistics.quantiles(sorted(v), n=4, method="inclusive")
    return q[0], statistics.median(v), q[2]


def fmt(x):
    return "inf" if math.isinf(x) else f"{x:.4g}"


def rank_sum_p(a, b):
    big = 1e300
    return mannwhitneyu([min(x, big) for x in a], [min(x, big) for x in b], alternative="two-sided").pvalue
