#!/usr/bin/python3
"""Error against run time of the cylinder kernel, per category, from `mtcs bench tolerance`.

Usage: plot_tolerance.py tolerance.csv out.png
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(src, dst):
    rows = list(csv.DictReader(open(src)))
    cats = sorted({r["category"] for r in rows if r["category"] != "all"})
    fig, (ax_err, ax_ns) = plt.subplots(1, 2, figsize=(11, 4.2))
    for cat in cats:
        rs = sorted((r for r in rows if r["category"] == cat), key=lambda r: float(r["tolerance"]))
        tol = [float(r["tolerance"]) for r in rs]
        # Errors of 0 are drawn at 1e-18 so that they stay on the log axis.
        err = [max(float(r["max_rel_err"]), 1e-18) for r in rs]
        ax_err.loglog(tol, err, "o-", label=f"{cat}: max error / max(1,S)")
        ax_ns.semilogx(tol, [float(r["median_ns"]) for r in rs], "o-", label=cat)
        ax_err.plot(tol, tol, color="grey", lw=0.8, ls=":")
    ax_err.axhline(1e-9, color="red", lw=0.8, ls="--", label="required 1e-9")
    ax_err.set_xlabel("tolerance of the numerical parts")
    ax_err.set_ylabel("max error against certified interval / max(1, S)")
    ax_err.legend(fontsize=8)
    ax_ns.set_xlabel("tolerance of the numerical parts")
    ax_ns.set_ylabel("median ns per query")
    ax_ns.legend(fontsize=8)
    ax_err.invert_xaxis()
    ax_ns.invert_xaxis()
    fig.suptitle("mtcs cylinder distance: error against run time")
    fig.tight_layout()
    fig.savefig(dst, dpi=110)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
