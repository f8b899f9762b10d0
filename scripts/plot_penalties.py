#!/usr/bin/python3
"""The plot of mtcs compare-penalties: final feasible-front hypervolume per variant (every seed, and
its median) and the feasible share of the evaluated layouts per tenth of the budget (median and
quartiles over seeds).

Usage: plot_penalties.py DIR   (reads DIR/runs.csv and DIR/feasible_share.csv; writes DIR/penalties.png)
"""
import csv
import math
import os
import statistics
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def quartiles(v):
    v = sorted(v)
    if len(v) == 1:
        return v[0], v[0], v[0]
    q = statistics.quantiles(v, n=4, method="inclusive")  # linear interpolation, as the table
    return q[0], statistics.median(v), q[2]


def main(d):
    runs = list(csv.DictReader(open(os.path.join(d, "runs.csv"))))
    shares = list(csv.DictReader(open(os.path.join(d, "feasible_share.csv"))))
    variants = list(dict.fromkeys(r["variant"] for r in runs))
    ref = runs[0]["reference_point"].split()
    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 4.5))

    for i, v in enumerate(variants):
        hv = [float(r["hypervolume"]) for r in runs if r["variant"] == v]
        q1, med, q3 = quartiles(hv)
        jitter = [i + 0.3 * (k - (len(hv) - 1) / 2) / max(1, len(hv)) for k in range(len(hv))]
        left.scatter(jitter, hv, s=18, alpha=0.7, color=f"C{i}")
        left.errorbar([i], [med], yerr=[[med - q1], [q3 - med]], fmt="_", markersize=30, capsize=8, color="k")
    left.set_xticks(range(len(variants)), variants, rotation=12)
    left.set_ylabel("final feasible-front hypervolume")
    left.set_title(f"HV (scaled objectives, reference point ({', '.join(ref)}))\nseeds as dots, median and IQR in black")

    for i, v in enumerate(variants):
        xs, med, lo, hi = [], [], [], []
        for dec in range(1, 11):
            vals = [float(s["share"]) for s in shares if s["variant"] == v and int(s["decile"]) == dec]
            vals = [x for x in vals if not math.isnan(x)]
            if not vals:
                continue
            q1, m, q3 = quartiles(vals)
            xs.append(10 * dec - 5)
            med.append(100 * m), lo.append(100 * q1), hi.append(100 * q3)
        right.plot(xs, med, marker="o", label=v, color=f"C{i}")
        right.fill_between(xs, lo, hi, alpha=0.15, color=f"C{i}")
    right.set_xlabel("budget spent (%): each point is one tenth")
    right.set_ylabel("feasible share of evaluated layouts (%)")
    right.set_ylim(-2, 102)
    right.set_title("feasible share over time (median, IQR band)")
    right.legend()
    fig.tight_layout()
    tmp = os.path.join(d, "penalties.png.tmp.png")
    fig.savefig(tmp, dpi=100)
    os.replace(tmp, os.path.join(d, "penalties.png"))  # nothing half-written


if __name__ == "__main__":
    main(sys.argv[1])
