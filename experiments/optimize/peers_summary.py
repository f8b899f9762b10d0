#!/usr/bin/python3
"""Tables, rank-sum tests and anytime plots of experiments/optimize/peers.

Usage: /usr/bin/python3 experiments/optimize/peers_summary.py [DIR]
Reads DIR/results_MOLD_BUDGET.csv and DIR/trace_MOLD_BUDGET.csv (mtcs bench optimize); writes
DIR/summary.md and DIR/anytime_MOLD_BUDGET.png.
"""
import csv
import glob
import math
import os
import re
import statistics
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from scipy.stats import mannwhitneyu  # noqa: E402

ALGS = ["es", "sms-emoa", "random", "isres", "crs2", "cmaes", "nsga2", "moead"]


def quartiles(v):
    v = sorted(v)
    if len(v) < 2:
        return v[0], v[0], v[0]
    q = statistics.quantiles(v, n=4, method="inclusive")
    return q[0], statistics.median(v), q[2]


def fmt(x):
    return "inf" if math.isinf(x) else f"{x:.4g}"


def ranksum(a, b):
    """Two-sided Wilcoxon rank-sum (Mann-Whitney U) p-value; inf values rank last."""
    big = 1e300
    a = [min(x, big) for x in a]
    b = [min(x, big) for x in b]
    return mannwhitneyu(a, b, alternative="two-sided").pvalue


def table(rows, mold, budget):
    out = [f"### {mold}, {budget} evaluations", "",
           "| algorithm | best weighted objective: median | IQR | feasible runs | HV: median | IQR | median s | "
           "p (best, vs es) | p (HV, vs sms-emoa) |",
           "|---|---:|---|---:|---:|---|---:|---:|---:|"]
    by = {a: [r for r in rows if r["algorithm"] == a] for a in ALGS}
    # Best objective: a run that found no feasible layout ranks last (inf).
    best = {a: [float(r["best_objective"]) if r["feasible"] == "1" else math.inf for r in rs] for a, rs in by.items()}
    hv = {a: [float(r["hypervolume"]) for r in rs] for a, rs in by.items()}
    for a in ALGS:
        rs = by[a]
        if not rs:
            continue
        q1, med, q3 = quartiles(best[a])
        h1, hm, h3 = quartiles(hv[a])
        feas = sum(int(r["feasible"]) for r in rs)
        secs = statistics.median(float(r["seconds"]) for r in rs)
        p_best = "" if a == "es" or not best["es"] else f"{ranksum(best['es'], best[a]):.2g}"
        p_hv = "" if a == "sms-emoa" or not hv["sms-emoa"] else f"{ranksum(hv['sms-emoa'], hv[a]):.2g}"
        out.append(f"| {a} | {fmt(med)} | {fmt(q1)}–{fmt(q3)} | {feas}/{len(rs)} | {fmt(hm)} | {fmt(h1)}–{fmt(h3)} | "
                   f"{secs:.2f} | {p_best} | {p_hv} |")
    return out + [""]


def anytime(trace_path, png, title):
    rows = list(csv.DictReader(open(trace_path)))
    fig, ax = plt.subplots(2, 2, figsize=(11, 8))
    for a in ALGS:
        rs = [r for r in rows if r["algorithm"] == a]
        if not rs:
            continue
        seeds = sorted({r["seed"] for r in rs})
        per_seed = [[r for r in rs if r["seed"] == s] for s in seeds]
        n = min(len(p) for p in per_seed)
        ev, sec, best, hv = [], [], [], []
        for k in range(n):
            ev.append(statistics.median(float(p[k]["evaluations"]) for p in per_seed))
            sec.append(statistics.median(float(p[k]["seconds"]) for p in per_seed))
            b = statistics.median(float(p[k]["best_feasible"]) for p in per_seed)
            best.append(b if math.isfinite(b) else float("nan"))
            hv.append(statistics.median(float(p[k]["hypervolume"]) for p in per_seed))
        ax[0][0].plot(ev, best, label=a)
        ax[0][1].plot(sec, best, label=a)
        ax[1][0].plot(ev, hv, label=a)
        ax[1][1].plot(sec, hv, label=a)
    ax[0][0].set_ylabel("median best feasible weighted objective")
    ax[1][0].set_ylabel("median feasible-front hypervolume (scaled)")
    for r in range(2):
        ax[r][0].set_xlabel("evaluations")
        ax[r][1].set_xlabel("wall seconds (shared machine)")
    ax[0][0].legend(fontsize=8)
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(png, dpi=90)
    plt.close(fig)


def main(d):
    lines = []
    # results_MOLD_BUDGET.csv only (variants such as results_MOLD_BUDGET_blend0.5.csv: compare.py).
    paths = [p for p in glob.glob(os.path.join(d, "results_*.csv")) if re.search(r"results_(.+)_(\d+)\.csv$", p)]
    for path in sorted(paths, key=lambda p: (int(re.search(r"_(\d+)\.csv$", p).group(1)), p)):
        m = re.search(r"results_(.+)_(\d+)\.csv$", path)
        mold, budget = m.group(1), m.group(2)
        rows = list(csv.DictReader(open(path)))
        if not rows:
            continue
        lines += table(rows, mold, budget)
        trace = os.path.join(d, f"trace_{mold}_{budget}.csv")
        if os.path.exists(trace):
            anytime(trace, os.path.join(d, f"anytime_{mold}_{budget}.png"), f"{mold}, {budget} evaluations, 11 seeds")
    open(os.path.join(d, "summary.md"), "w").write("\n".join(lines))
    print("\n".join(lines))


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "peers"))
