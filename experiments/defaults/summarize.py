#!/usr/bin/env python3
"""Per mold and algorithm, from a CSV of run.sh rows: seeds run, feasible, >= 3 circuits, worst
covered <= 4 D mm (every cavity-surface sample within 4 drill diameters of a bore's wall, the
largest drill of the mold: docs in README.md), medians; for SMS-EMOA fronts of >= 5 distinct
designs and hypervolume > 0. Usage: summarize.py CSV"""
import csv, os, re, statistics, sys

here = os.path.dirname(os.path.abspath(__file__))


def largest_drill(mold):
    """The largest of the mold's drilling.diameters (mm), from its spec file."""
    for d in ("../../molds", "../../docs/first-mold", "."):
        p = os.path.join(here, d, mold)
        if os.path.exists(p):
            m = re.search(r"diameters:\s*\[([^\]]*)\]", open(p).read())
            return max(float(v) for v in m.group(1).split(",")) if m else 8.0
    return 8.0


rows = list(csv.DictReader(open(sys.argv[1])))
groups = {}
for r in rows:
    groups.setdefault((r["mold"], r["algorithm"]), []).append(r)
print("| mold | algorithm | seeds | feasible | >= 3 circuits | reach (worst_covered <= 4 D) | worst_covered median (min-max), mm | >= 5 distinct designs | HV > 0 |")
print("|---|---|---|---|---|---|---|---|---|")
for (mold, algo), rs in groups.items():
    ok = [r for r in rs if r["feasible"] in ("0", "1")]
    n = len(rs)
    feas = sum(r["feasible"] == "1" for r in ok)
    circ = sum(int(r["circuits"]) >= 3 for r in ok)
    reach = 4 * largest_drill(mold)
    wc = [float(r["worst_covered_mm"]) for r in ok if r["worst_covered_mm"]]
    reached = sum(w <= reach for w in wc)
    wtxt = f"{statistics.median(wc):.1f} ({min(wc):.1f}-{max(wc):.1f})" if wc else "-"
    rtxt = f"{reached}/{n} (<= {reach:g} mm)" if wc else "- (temperatures)"
    if algo == "sms-emoa":
        distinct = f"{sum(int(r['distinct_front'] or 0) >= 5 for r in ok)}/{n}"
        hv = f"{sum(float(r['hypervolume'] or 0) > 0 for r in ok)}/{n}"
    else:
        distinct = hv = "-"
    print(f"| {mold} | {algo} | {n} | {feas}/{n} | {circ}/{n} | {rtxt} | {wtxt} | {distinct} | {hv} |")
