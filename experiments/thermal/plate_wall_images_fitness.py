"""The plate's own scalar fitness (temperature_std / 1 + temperature_max / 10 + cost / 1000, the
scales of molds/plate.yaml) of each best layout of two study arms, the temperatures from T3 (the
study's CSV) and the cost from `mtcs evaluate`; medians and the exact rank-sum test.
  python3 plate_wall_images_fitness.py A.csv A_LAYOUTS B.csv B_LAYOUTS   (from the repository root)"""
import csv
import json
import statistics
import subprocess
import sys

from rank_sum import p_exact  # this folder


def arm(table, layouts):
    out = []
    for r in csv.DictReader(open(table)):
        layout = f"{layouts}/spec-{r['seed']}.layout.yaml"
        ev = subprocess.run(["./build/mtcs", "evaluate", "molds/plate.yaml", "--layout", layout, "--json"],
                            capture_output=True, text=True, check=True)
        cost = json.loads(ev.stdout)["objectives"]["cost"]
        std, tmax = float(r["t3_std_k"]), float(r["t3_max_c"])
        out.append({"seed": r["seed"], "std": std, "max": tmax, "cost": cost, "fitness": std + tmax / 10 + cost / 1000,
                    "seconds": float(r["seconds"]), "bores": r["bores"]})
    return out


a, b = arm(sys.argv[1], sys.argv[2]), arm(sys.argv[3], sys.argv[4])
print("arm,seed,t3_std_k,t3_max_c,cost,t3_fitness,seconds,bores")
for name, x in ((sys.argv[1], a), (sys.argv[3], b)):
    for v in x:
        print(f"{name},{v['seed']},{v['std']:.4f},{v['max']:.4f},{v['cost']:.1f},{v['fitness']:.4f},{v['seconds']},{v['bores']}")
for name, x in ((sys.argv[1], a), (sys.argv[3], b)):
    med = {k: statistics.median(v[k] for v in x) for k in ("std", "max", "cost", "fitness", "seconds")}
    print(f"# {name}: median T3 std {med['std']:.3f} K, max {med['max']:.2f} C, cost {med['cost']:.0f}, "
          f"fitness {med['fitness']:.3f}, run {med['seconds']:.2f} s")
u = sum(p["fitness"] < q["fitness"] for p in a for q in b)
print(f"# U = {u} of {len(a) * len(b)} pairs have the first's layout fitter under T3; "
      f"exact two-sided p = {p_exact(len(a), len(b), u):.2f}")
