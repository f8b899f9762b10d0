#!/usr/bin/python3
"""Front plots of mtcs replay: one PNG per replayed generation, each objective pair as a panel,
the same axes in every frame (an animation holds still).

Usage: plot_fronts.py REPLAY/frames.json   (written by mtcs replay: objective names, axis limits,
and per frame its generation, evaluations, front JSON and PNG name; the PNGs go beside it)
"""
import itertools
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def padded(lo, hi):
    pad = 0.05 * (hi - lo) if hi > lo else max(abs(lo), 1.0) * 0.05
    return lo - pad, hi + pad


def main(path):
    d = os.path.dirname(os.path.abspath(path))
    spec = json.load(open(path))
    names = spec["objectives"]
    limits = [padded(lo, hi) for lo, hi in spec["limits"]]
    pairs = list(itertools.combinations(range(len(names)), 2))
    fig, axes = plt.subplots(1, len(pairs), figsize=(4.2 * len(pairs), 4), squeeze=False)
    dots = []
    for ax, (i, j) in zip(axes[0], pairs):
        ax.set_xlim(*limits[i])
        ax.set_ylim(*limits[j])
        ax.set_xlabel(names[i])
        ax.set_ylabel(names[j])
        ax.grid(alpha=0.3)
        dots.append(ax.scatter([], [], s=22, color="C0"))
    # One figure, its points replaced frame by frame: hundreds of frames stay fast.
    for n, frame in enumerate(spec["frames"]):
        front = json.load(open(os.path.join(d, frame["front"])))["front"]
        points = [[m["objectives"][name] for name in names] for m in front]
        for dot, (i, j) in zip(dots, pairs):
            dot.set_offsets([[p[i], p[j]] for p in points] if points else [[float("nan"), float("nan")]])
        fig.suptitle(f"generation {frame['generation']}, {frame['evaluations']} evaluations: "
                     f"{len(points)} feasible non-dominated layouts")
        if n == 0:
            fig.tight_layout()
        tmp = os.path.join(d, frame["png"] + ".tmp.png")
        fig.savefig(tmp, dpi=80)
        os.replace(tmp, os.path.join(d, frame["png"]))  # nothing half-written
        if (n + 1) % 100 == 0 or n + 1 == len(spec["frames"]):
            print(f"front plots: {n + 1}/{len(spec['frames'])}", flush=True)


if __name__ == "__main__":
    main(sys.argv[1])
