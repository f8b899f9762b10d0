"""Why does T2d rank the plate's layouts badly against T3? Per-sample temperatures of T2d and
T3 (mtcs thermal --samples) at the plate's cavity samples, for a set of layouts; Kendall tau of
the area-weighted std between the tiers over (a) every cavity sample, (b) the heated samples
(flux > 0: the faces this mold half cools), (c) the lower face only; the per-face mean offset
T2d - T3.

  python3 experiments/thermal/plate_diagnosis.py OUT_DIR LAYOUT.yaml... [--cell 3] [--jobs 2]

The samples replicate src/eval/surface_samples.cpp's sample_box for molds/plate.yaml's box cavity
(the script checks its std over every sample against mtcs's own --json figure). Solves are cached
in OUT_DIR (rerunning only computes what is missing). Writes OUT_DIR/diagnosis.csv.
"""
import argparse
import concurrent.futures
import csv
import json
import math
import os
import subprocess
import sys

MOLD = "molds/plate.yaml"
CAVITY = ((50.0, 25.0, 105.0), (250.0, 175.0, 108.0))
SPACING = 5.5
HEATED_ZMAX = 107.0  # thermal.regions: no flux at z >= 107 (the top face)
FACE_NAMES = {(0, 0): "-x", (0, 1): "+x", (1, 0): "-y", (1, 1): "+y", (2, 0): "lower", (2, 1): "top"}


def samples():
    lo, hi = CAVITY
    out = []
    for k in range(3):
        i, j = (k + 1) % 3, (k + 2) % 3
        ni = max(1, math.ceil((hi[i] - lo[i]) / SPACING))
        nj = max(1, math.ceil((hi[j] - lo[j]) / SPACING))
        di, dj = (hi[i] - lo[i]) / ni, (hi[j] - lo[j]) / nj
        for side, plane in enumerate((lo[k], hi[k])):
            for a in range(ni):
                for b in range(nj):
                    p = [0.0, 0.0, 0.0]
                    p[k], p[i], p[j] = plane, lo[i] + (a + 0.5) * di, lo[j] + (b + 0.5) * dj
                    out.append({"p": p, "w": di * dj, "face": FACE_NAMES[(k, side)],
                                "heated": p[2] < HEATED_ZMAX})
    return out


def wstd(values, weights):
    w = sum(weights)
    mean = sum(v * x for v, x in zip(values, weights)) / w
    return math.sqrt(sum(x * (v - mean) ** 2 for v, x in zip(values, weights)) / w), mean


def kendall(a, b):
    n, s = len(a), 0
    for i in range(n):
        for j in range(i + 1, n):
            s += ((a[i] > a[j]) - (a[i] < a[j])) * ((b[i] > b[j]) - (b[i] < b[j]))
    return s / (n * (n - 1) / 2)


def solve(out_dir, layout, tier, cell, points):
    name = os.path.basename(layout).replace(".layout.yaml", "")
    tag = f"{name}.{tier}" + (f"{cell:g}" if tier == "fd" else "")
    csv_path, json_path = os.path.join(out_dir, tag + ".csv"), os.path.join(out_dir, tag + ".json")
    if not (os.path.exists(csv_path) and os.path.exists(json_path)):
        cmd = [os.environ.get("MTCS", "./build/mtcs"), "thermal", MOLD, "--layout", layout, "--tier", tier, "--samples", points,
               "--out", csv_path, "--json"]
        if tier == "fd":
            cmd += ["--cell", str(cell)]
        res = subprocess.run(cmd, check=True, capture_output=True, text=True)
        open(json_path, "w").write(res.stdout)
    t = [float(r["T"]) for r in csv.DictReader(open(csv_path))]
    return name, tier, t, json.load(open(json_path))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("out_dir")
    ap.add_argument("layouts", nargs="+")
    ap.add_argument("--cell", type=float, default=3)
    ap.add_argument("--jobs", type=int, default=2)
    args = ap.parse_args()
    os.makedirs(args.out_dir, exist_ok=True)
    s = samples()
    points = os.path.join(args.out_dir, "samples.csv")
    with open(points, "w") as f:
        f.write("x,y,z\n" + "".join(f"{q['p'][0]!r},{q['p'][1]!r},{q['p'][2]!r}\n" for q in s))
    res = {}
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        jobs = [pool.submit(solve, args.out_dir, l, tier, args.cell, points) for l in args.layouts
                for tier in ("t2d", "fd")]
        for job in jobs:
            name, tier, t, summary = job.result()
            res.setdefault(name, {})[tier] = (t, summary)
    subsets = {"all": lambda q: True, "heated": lambda q: q["heated"], "lower": lambda q: q["face"] == "lower",
               "top": lambda q: q["face"] == "top", "sides": lambda q: q["face"] not in ("lower", "top")}
    rows = []
    for name in sorted(res):
        row = {"layout": name}
        for tier in ("t2d", "fd"):
            t, summary = res[name][tier]
            assert len(t) == len(s), (name, tier, len(t))
            # The script's samples are mtcs's: the same std over the surface mtcs summarises.
            keep = [q["heated"] or summary.get("surface", "all") == "all" for q in s]
            check, _ = wstd([v for v, k in zip(t, keep) if k], [q["w"] for q, k in zip(s, keep) if k])
            assert abs(check - summary["std"]) < 1e-6 * max(1, summary["std"]), (name, tier, check, summary["std"])
            for sub, keep in subsets.items():
                idx = [n for n, q in enumerate(s) if keep(q)]
                sd, mean = wstd([t[n] for n in idx], [s[n]["w"] for n in idx])
                row[f"{tier}_std_{sub}"], row[f"{tier}_mean_{sub}"] = sd, mean
                row[f"{tier}_max_{sub}"] = max(t[n] for n in idx)
        rows.append(row)
    with open(os.path.join(args.out_dir, "diagnosis.csv"), "w") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    print(f"{len(rows)} layouts, {len(s)} samples ({sum(q['heated'] for q in s)} heated), T3 cell {args.cell:g} mm")
    for sub in subsets:
        a, b = [r[f"t2d_std_{sub}"] for r in rows], [r[f"fd_std_{sub}"] for r in rows]
        off = sorted(r[f"t2d_mean_{sub}"] - r[f"fd_mean_{sub}"] for r in rows)
        print(f"{sub:7s} tau(std) {kendall(a, b):+.3f}   median std t2d {sorted(a)[len(a) // 2]:.3f} K, "
              f"fd {sorted(b)[len(b) // 2]:.3f} K   mean offset t2d - fd: median {off[len(off) // 2]:+.2f} K "
              f"(range {off[0]:+.2f} .. {off[-1]:+.2f})")


if __name__ == "__main__":
    sys.exit(main())
