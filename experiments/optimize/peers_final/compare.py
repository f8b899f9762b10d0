#!/usr/bin/python3
"""Every algorithm on every mold at 20 000 and 100 000 evaluations, 11 seeds: the shipped ES on
the best weighted objective and SMS-EMOA on the hypervolume, each against every peer (NSGA-II,
MOEA/D, CMA-ES, ISRES, CRS2): median, IQR and two-sided rank-sum p.

Usage: /usr/bin/python3 experiments/optimize/peers_final/compare.py   (writes compare.md here)
Rows: this folder (SMS-EMOA, thermal_block at 100k, CMA-ES/ISRES/CRS2), ../peers_restart/ (the
shipped ES: *_fixed; SMS-EMOA at 20k on cup and plate: sms_*), ../peers_moves/ (NSGA-II and MOEA/D, which do not depend on the ES's config).
"""
import os
import statistics
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(here))
from peers_stats import fmt, quartiles, rank_sum_p, results  # noqa: E402

molds = ["cup", "plate_wall_distance", "gear", "thermal_block"]
budgets = [20000, 100000]
peers = ["nsga2", "moead", "cmaes", "isres", "crs2"]


def arms(mold, budget, column, extra=lambda mold, budget: []):
    """{algorithm: values} from every file that holds the cell, later files first come; `extra`
    names more files, read last (another study's arms of ours)."""
    files = [os.path.join(here, "..", "peers_moves", f"results_{mold}_{budget}{s}.csv") for s in ["", "_moead"]]
    files += [os.path.join(here, "..", "peers_restart", f) for f in [f"results_{mold}_{budget}_fixed.csv",  # the shipped ES
                                                                      f"sms_{mold}_{budget}.csv"]]
    files += [os.path.join(here, f"results_{mold}_{budget}_{s}.csv") for s in ["sms", "all", "classic", "classic_rest"]]
    files += extra(mold, budget)
    out = {}
    for f in files:
        out.update(results(f, column))
    return {a: v for a, v in out.items() if len(v) == 11}  # a cell still running is not an arm yet


def section(title, ours, column, better, extra):
    lines = [f"## {title}", "", "| mold | budget | " + ours + " median (IQR) | " +
             " | ".join(f"{p} median, p" for p in peers) + " | beats every peer |",
             "|---|---|---:|" + "---:|" * len(peers) + "---|"]
    for mold in molds:
        for budget in budgets:
            a = arms(mold, budget, column, extra)
            if ours not in a:
                continue
            q1, med, q3 = quartiles(a[ours])
            cols = [mold, f"{budget // 1000}k", f"**{fmt(med)}** ({fmt(q1)}-{fmt(q3)})"]
            wins, measured = True, 0
            for peer in peers:
                if peer not in a:
                    cols.append("-")
                    continue
                measured += 1
                pm, pv = statistics.median(a[peer]), rank_sum_p(a[ours], a[peer])
                cols.append(f"{fmt(pm)}, {pv:.2g}")
                wins = wins and pv < 0.05 and better(med, pm)
            cols.append(("yes" if wins else "**no**") + f" ({measured} peers)")
            lines.append("| " + " | ".join(cols) + " |")
    return lines + [""]


def write(title, script, out, extra=lambda mold, budget: []):
    lines = [title, "",
             f"Made by `/usr/bin/python3 {script}`. p: two-sided rank-sum",
             "(Mann-Whitney U). A run without a feasible layout has best objective inf. Hypervolume: feasible",
             "non-dominated layouts evaluated, scaled objectives, the reference point of `mtcs-bench` (stderr_*.txt).", ""]
    lines += section("The ES: best weighted objective (lower is better)", "es", "best_objective", lambda a, b: a < b, extra)
    lines += section("SMS-EMOA: hypervolume (higher is better)", "sms-emoa", "hypervolume", lambda a, b: a > b, extra)
    lines += section("The ES: hypervolume of the layouts it evaluated (higher is better)", "es", "hypervolume",
                     lambda a, b: a > b, extra)
    open(out, "w").write("\n".join(lines))
    print("\n".join(lines))


if __name__ == "__main__":
    write("# The shipped ES and SMS-EMOA against every peer, 11 seeds", "experiments/optimize/peers_final/compare.py",
          os.path.join(here, "compare.md"))
