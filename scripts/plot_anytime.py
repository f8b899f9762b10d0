#!/usr/bin/python3
"""Anytime plot of a replayed run: best feasible objective and front hypervolume against
evaluations and against wall time.

Usage: plot_anytime.py DIR/replay/anytime.csv   (writes anytime.png beside it)
"""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(path):
    rows = list(csv.DictReader(open(path)))
    if not rows:
        return
    col = {k: [float(r[k]) for r in rows] for k in rows[0]}
    fig, axes = plt.subplots(2, 2, figsize=(10, 7), sharey="row")
    for row, (key, label) in enumerate([("best_so_far", "best feasible objective (lower is better)"),
                                        ("hypervolume_so_far", "front hypervolume (scaled objectives)")]):
        y = [v if math.isfinite(v) else float("nan") for v in col[key]]
        for c, (xkey, xlabel) in enumerate([("evaluations", "evaluations"), ("seconds", "wall time, s")]):
            ax = axes[row][c]
            ax.plot(col[xkey], y, drawstyle="steps-post")
            ax.set_xlabel(xlabel)
            if c == 0:
                ax.set_ylabel(label)
            ax.grid(alpha=0.3)
    fig.suptitle("anytime behaviour (stored generations)")
    fig.tight_layout()
    fig.savefig(os.path.join(os.path.dirname(os.path.abspath(path)), "anytime.png"), dpi=100)


if __name__ == "__main__":
    main(sys.argv[1])
