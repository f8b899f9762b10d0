"""Ranks the plate's layouts by T2d's temperature std with 2 and 1 reflection levels summed exactly
at the walls (plate_wall_images.cpp's CSV) against T3 at 3 mm (plate_samples.csv's fd3 rows).
usage: python3 plate_wall_images.py plate_wall_images.csv plate_samples.csv"""
import csv
import statistics
import sys

from scipy.stats import kendalltau

rows = list(csv.DictReader(open(sys.argv[1])))
truth = {(r["set"], r["layout"]): float(r["std"]) for r in csv.DictReader(open(sys.argv[2])) if r["tier"] == "fd3"}
groups = {"random (120)": lambda s: s.startswith("random"), "ES results (33)": lambda s: s.startswith("es:")}
print("| layouts | wall levels | tau(std) vs T3 | tau, better half | \\|d std\\| vs 2 levels, median / max (K) | cold solve ms, median |")
print("|---|---|---|---|---|---|")
for name, member in groups.items():
    by = {k: {(r["set"], r["layout"]): r for r in rows if r["wall_images"] == k and member(r["set"])} for k in ("2", "1")}
    keys = sorted(k for k in by["2"] if k in truth)
    t = [truth[k] for k in keys]
    half = sorted(keys, key=lambda k: truth[k])[: len(keys) // 2]
    for lv in ("2", "1"):
        s = [float(by[lv][k]["std"]) for k in keys]
        tau = kendalltau(t, s)[0]
        tau_half = kendalltau([truth[k] for k in half], [float(by[lv][k]["std"]) for k in half])[0]
        d = [abs(float(by[lv][k]["std"]) - float(by["2"][k]["std"])) for k in keys]
        ms = statistics.median(float(by[lv][k]["ms"]) for k in keys)
        print(f"| {name} | {lv} | {tau:.3f} | {tau_half:.3f} | {statistics.median(d):.3f} / {max(d):.3f} | {ms:.2f} |")
