#!/usr/bin/python3
"""Summary table and convergence plot of experiments/optimize.

Usage: plot_convergence.py DIR   (reads DIR/results.csv and DIR/trace_MOLD_ALG.csv; writes
DIR/summary.md and DIR/convergence.png)
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
    q = statistics.quantiles(v, n=4, method="inclusive") if len(v) > 1 else [v[0]] * 3
    return q[0], statistics.median(v), q[2]


def main(d):
    rows = list(csv.DictReader(open(os.path.join(d, "results.csv"))))
    molds = sorted({r["mold"] for r in rows})
    algs = ["es", "random", "nlopt", "nlopt-ref"]
    lines = ["| mold | algorithm | median best | IQR | feasible runs | median seconds |", "|---|---|---:|---|---:|---:|"]
    for m in molds:
        for a in algs:
            rs = [r for r in rows if r["mold"] == m and r["algorithm"] == a]
            if not rs:
                continue
            best = [float(r["best_objective"]) for r in rs]
            q1, med, q3 = quartiles(best)
            feas = sum(int(r["feasible"]) for r in rs)
            secs = statistics.median(float(r["seconds"]) for r in rs)
            lines.append(f"| {os.path.basename(m)} | {a} | {med:.4g} | {q1:.4g}–{q3:.4g} | {feas}/{len(rs)} | {secs:.2f} |")
    open(os.path.join(d, "summary.md"), "w").write("\n".join(lines) + "\n")
    print("\n".join(lines))

    fig, axes = plt.subplots(1, len(molds), figsize=(6 * len(molds), 4.2), squeeze=False)
    for ax, m in zip(axes[0], molds):
        name = os.path.splitext(os.path.basename(m))[0]
        for a in algs:
            path = os.path.join(d, f"trace_{name}_{a}.csv")
            if not os.path.exists(path):
                continue
            traces = {}
            for r in csv.DictReader(open(path)):
                traces.setdefault(r["seed"], []).append((int(r["evaluations"]), float(r["best_feasible"])))
            grid = list(range(500, 20001, 500))
            med = []
            for g in grid:
                vals = []
                for t in traces.values():
                    best = math.inf
                    for e, b in t:
                        if e <= g:
                            best = b
                    vals.append(best)
                finite = [v for v in vals if math.isfinite(v)]
                med.append(statistics.median(vals) if len(finite) > len(vals) / 2 else math.nan)
            ax.plot(grid, med, label=a)
        ax.set_title(f"{name}: median best feasible objective (11 seeds)")
        ax.set_xlabel("evaluations")
        ax.set_ylabel("scalarised objective (lower is better)")
        ax.set_yscale("log")
        ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(d, "convergence.png"), dpi=100)


if __name__ == "__main__":
    main(sys.argv[1])
