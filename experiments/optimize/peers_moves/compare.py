#!/usr/bin/python3
"""The ES with and without mutation.blend against NSGA-II and MOEA/D: median, IQR, feasible runs,
median seconds and two-sided rank-sum p-values (Mann-Whitney U, scipy) on the best weighted
objective (a run without a feasible layout counts as inf), each row against es and es+blend;
the hypervolume of the feasible non-dominated layouts evaluated (scaled objectives, the
reference point of mtcs-bench) against es's.

Usage: /usr/bin/python3 experiments/optimize/peers_moves/compare.py [BUDGET]
Reads results_MOLD_BUDGET.csv (es, nsga2, moead) and results_MOLD_BUDGET_VARIANT.csv (the ES of
another config or binary, labelled es+VARIANT: blend* with es_blend*.yaml, reach after the reach
move); writes compare_BUDGET.md next to them.
"""
import csv
import glob
import math
import os
import statistics
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(here))
from peers_stats import fmt, quartiles, rank_sum_p as p  # noqa: E402
budget = sys.argv[1] if len(sys.argv) > 1 else "20000"


def runs(path, rename=None):
    out = {}
    with open(path) as f:
        for r in csv.DictReader(f):
            a = rename if rename and r["algorithm"] == "es" else r["algorithm"]  # a peer's file keeps its name
            out.setdefault(a, []).append((float(r["best_objective"]) if r["feasible"] == "1" else math.inf,
                                          float(r["seconds"]), float(r["hypervolume"])))
    return out



lines = [f"# ES variants against NSGA-II and MOEA/D, {budget} evaluations, 11 seeds", ""]
for mold in ["cup", "plate_wall_distance", "gear", "thermal_block"]:
    base = os.path.join(here, f"results_{mold}_{budget}.csv")
    if not os.path.exists(base) or not os.path.getsize(base):
        continue
    algs = runs(base)
    for path in sorted(glob.glob(os.path.join(here, f"results_{mold}_{budget}_*.csv"))):
        label = "es+" + os.path.basename(path)[len(f"results_{mold}_{budget}_"):-4]
        algs.update(runs(path, label))
    order = ["es"] + sorted(a for a in algs if a.startswith("es+")) + [a for a in ["nsga2", "moead"] if a in algs]
    blends = [a for a in order if a.startswith("es+")]
    lines += [f"## {mold}", "",
              "| " + " | ".join(["algorithm", "best: median", "IQR", "feasible", "HV median", "p (HV, vs es)", "median s",
                                  "p vs es"] + [f"p vs {b}" for b in blends]) + " |",
              "|---|---:|---|---:|---:|---:|---:|---:|" + "---:|" * len(blends)]
    for a in order:
        best = [r[0] for r in algs[a]]
        q1, med, q3 = quartiles(best)
        row = [a, fmt(med), f"{fmt(q1)}–{fmt(q3)}", f"{sum(math.isfinite(x) for x in best)}/{len(best)}",
               fmt(statistics.median(r[2] for r in algs[a])),
               "" if a == "es" else f"{p([r[2] for r in algs[a]], [r[2] for r in algs['es']]):.2g}",
               f"{statistics.median(r[1] for r in algs[a]):.2f}",
               "" if a == "es" else f"{p(best, [r[0] for r in algs['es']]):.2g}"]
        row += ["" if a == b else f"{p(best, [r[0] for r in algs[b]]):.2g}" for b in blends]
        lines.append("| " + " | ".join(row) + " |")
    lines.append("")
    # The anytime course from the traces: median best feasible objective at fractions of the
    # budget (a seed without a feasible layout yet counts as inf), rank-sum against nsga2.
    traces = {}
    for path in [os.path.join(here, f"trace_{mold}_{budget}.csv")] + sorted(glob.glob(os.path.join(here, f"trace_{mold}_{budget}_*.csv"))):
        label = None if path.endswith(f"_{budget}.csv") else "es+" + os.path.basename(path)[len(f"trace_{mold}_{budget}_"):-4]
        with open(path) as f:
            for r in csv.DictReader(f):
                a = label if label and r["algorithm"] == "es" else r["algorithm"]
                traces.setdefault(a, {}).setdefault(r["seed"], []).append((int(r["evaluations"]), float(r["best_feasible"])))
    marks = [int(int(budget) * q) for q in (0.1, 0.25, 0.5, 1.0)]

    def at(a, e):  # per seed, the best so far at e evaluations (the last point at or before e)
        return [min([v for n, v in pts if n <= e + 30] or [math.inf]) for pts in traces[a].values()]
    lines += [f"Anytime, {mold}: median best feasible objective (p vs nsga2)", "",
              "| algorithm | " + " | ".join(f"{m} evaluations" for m in marks) + " |", "|---|" + "---:|" * len(marks)]
    for a in order:
        if a not in traces:
            continue
        cells = []
        for m in marks:
            v = at(a, m)
            cells.append(fmt(statistics.median(v)) + ("" if a == "nsga2" else f" ({p(v, at('nsga2', m)):.2g})"))
        lines.append(f"| {a} | " + " | ".join(cells) + " |")
    lines.append("")
with open(os.path.join(here, f"compare_{budget}.md"), "w") as f:
    f.write("\n".join(lines))
print("\n".join(lines))
