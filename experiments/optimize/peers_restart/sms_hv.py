#!/usr/bin/python3
"""SMS-EMOA's hypervolume at 20 000 evaluations against NSGA-II's, MOEA/D's and the ES's (the
hypervolume of the feasible non-dominated layouts each run evaluated, scaled objectives, the
reference point of mtcs-bench), 11 seeds: median, IQR and two-sided rank-sum p.

Usage: /usr/bin/python3 experiments/optimize/peers_restart/sms_hv.py   (writes sms_hv.md here)
Reads sms_MOLD_20000.csv here, ../peers_moves/results_MOLD_20000.csv (nsga2, moead) and the ES
with restart (results_MOLD_20000_pop200.csv here).
"""
import csv
import os
import statistics

from scipy.stats import mannwhitneyu

here = os.path.dirname(os.path.abspath(__file__))


def hv(path):
    out = {}
    with open(path) as f:
        for r in csv.DictReader(f):
            out.setdefault(r["algorithm"], []).append(float(r["hypervolume"]))
    return out


lines = ["# SMS-EMOA's hypervolume against the peers and the ES, 20 000 evaluations, 11 seeds", "",
         "| mold | algorithm | HV median | IQR | p (HV, vs sms-emoa) |", "|---|---|---:|---|---:|"]
for mold in ["cup", "plate_wall_distance"]:
    algs = hv(os.path.join(here, f"sms_{mold}_20000.csv"))
    peers = hv(os.path.join(here, "..", "peers_moves", f"results_{mold}_20000.csv"))
    algs["nsga2"], algs["moead"] = peers["nsga2"], peers["moead"]
    algs["es (restart default)"] = hv(os.path.join(here, f"results_{mold}_20000_pop200.csv"))["es"]
    for a, v in algs.items():
        q = statistics.quantiles(sorted(v), n=4, method="inclusive")
        pv = "" if a == "sms-emoa" else f"{mannwhitneyu(v, algs['sms-emoa'], alternative='two-sided').pvalue:.2g}"
        lines.append(f"| {mold} | {a} | {statistics.median(v):.4g} | {q[0]:.4g}–{q[2]:.4g} | {pv} |")
lines.append("")
open(os.path.join(here, "sms_hv.md"), "w").write("\n".join(lines))
print("\n".join(lines))
