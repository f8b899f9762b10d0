#!/usr/bin/python3
"""The ES with restart on stall against today's ES (es+reach, no restart) and the peers NSGA-II
and MOEA/D, per cell (mold, budget): median and IQR of the best weighted objective (a run
without a feasible layout counts as inf), feasible runs, and two-sided rank-sum p-values
(Mann-Whitney U, scipy), 11 seeds each.

Usage: /usr/bin/python3 experiments/optimize/peers_restart/compare.py [LABEL ...]
Reads results_MOLD_BUDGET_LABEL.csv here (default: every label found) and the ES and peer rows
of ../peers_moves/ (which do not depend on the ES's config); writes compare.md here.
"""
import glob
import math
import os
import statistics
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(here))
from peers_stats import fmt, quartiles, rank_sum_p as p, results as rows  # noqa: E402
moves = os.path.join(here, "..", "peers_moves")
cells = [("cup", 20000), ("cup", 100000), ("plate_wall_distance", 20000), ("plate_wall_distance", 100000),
         ("gear", 20000), ("gear", 100000), ("thermal_block", 20000)]


def arms(mold, budget):
    """{name: best values}: es (today's default, no restart), nsga2, moead."""
    base = rows(os.path.join(moves, f"results_{mold}_{budget}.csv"))
    reach = rows(os.path.join(moves, f"results_{mold}_{budget}_reach.csv"))
    moead = rows(os.path.join(moves, f"results_{mold}_{budget}_moead.csv"))
    out = {"es": (reach or base)["es"]}
    out["nsga2"] = base.get("nsga2")
    out["moead"] = base.get("moead") or moead.get("moead")
    return out


labels = sys.argv[1:] or sorted({os.path.basename(f).rsplit("_", 1)[1][:-4] for f in glob.glob(os.path.join(here, "results_*_*_*.csv"))})
lines = ["# The ES with restart on stall against today's ES and the peers, 11 seeds", "",
         "`es`: the ES without restart (../peers_moves/, es+reach for cup and plate). p: two-sided rank-sum.", "",
         "| mold | budget | arm | median | IQR | feasible | p vs es | p vs NSGA-II | p vs MOEA/D | beats both (median, p < 0.05) |",
         "|---|---|---|---:|---|---:|---:|---:|---:|---|"]
for mold, budget in cells:
    a = arms(mold, budget)
    shown = [("es", a["es"])] + [(f"es+{l}", rows(os.path.join(here, f"results_{mold}_{budget}_{l}.csv")).get("es")) for l in labels]
    for name, best in shown:
        if not best:
            continue
        q1, med, q3 = quartiles(best)
        cols = [mold, f"{budget // 1000}k", name, fmt(med), f"{fmt(q1)}–{fmt(q3)}", f"{sum(math.isfinite(x) for x in best)}/{len(best)}",
                "" if name == "es" else f"{p(best, a['es']):.2g}"]
        wins = True
        for peer in ["nsga2", "moead"]:
            if a[peer]:
                pv = p(best, a[peer])
                cols.append(f"{pv:.2g}")
                wins = wins and pv < 0.05 and med < statistics.median(a[peer])
            else:
                cols.append("")
        cols.append("yes" if wins else "**no**")
        lines.append("| " + " | ".join(cols) + " |")
    for peer in ["nsga2", "moead"]:
        if a[peer]:
            q1, med, q3 = quartiles(a[peer])
            lines.append(f"| {mold} | {budget // 1000}k | {peer} | {fmt(med)} | {fmt(q1)}–{fmt(q3)} | "
                         f"{sum(math.isfinite(x) for x in a[peer])}/{len(a[peer])} | | | | |")
lines.append("")
with open(os.path.join(here, "compare.md"), "w") as f:
    f.write("\n".join(lines))
print("\n".join(lines))
