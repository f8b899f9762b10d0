#!/usr/bin/python3
"""Heat map of an accessibility map written by `mtcs access-map MESH ... --out am.csv`: the
sphere grid unrolled (gamma about z across, phi from +z down), free directions light, colliding
ones dark, with the share of free directions in the title.

Usage: plot_access_map.py AM.csv OUT.png [TITLE]
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.colors import ListedColormap  # noqa: E402


def read_map(path):
    with open(path) as f:
        rows = [(float(r["phi"]), float(r["gamma"]), int(r["free"])) for r in csv.DictReader(f)]
    phis = sorted({r[0] for r in rows})
    gammas = sorted({r[1] for r in rows})
    pi = {p: i for i, p in enumerate(phis)}
    gi = {g: j for j, g in enumerate(gammas)}
    grid = [[0] * len(gammas) for _ in phis]
    for phi, gamma, free in rows:
        grid[pi[phi]][gi[gamma]] = free
    return grid


def main(path, out, title=""):
    grid = read_map(path)
    rows, cols = len(grid), len(grid[0])
    free = sum(map(sum, grid))
    fig, ax = plt.subplots(figsize=(8, 4.6))
    ax.imshow(grid, cmap=ListedColormap(["#3b3b3b", "#f2c14e"]), vmin=0, vmax=1, origin="upper",
              extent=(0, 360, 180, 0), aspect="auto", interpolation="nearest")
    ax.set_xlabel("gamma: angle about z (degrees)")
    ax.set_ylabel("phi: angle from +z (degrees)")
    ax.set_xticks(range(0, 361, 45))
    ax.set_yticks(range(0, 181, 30))
    share = 100.0 * free / (rows * cols)
    ax.set_title(f"{title}\nfree directions (light): {free} of {rows * cols} ({share:.1f} %)" if title
                 else f"free directions (light): {free} of {rows * cols} ({share:.1f} %)")
    fig.tight_layout()
    fig.savefig(out, dpi=120)


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2], sys.argv[3] if len(sys.argv) > 3 else "")
