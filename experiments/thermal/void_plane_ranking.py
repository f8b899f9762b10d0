"""How well does a line-sink tier rank the plate's layouts as T3 does? For each FIELDS_DIR (per-
sample fields NAME.t2d.csv and NAME.fd3.csv at plate_diagnosis.py's samples, as
es_plate_physics_vs_distance.sh FIELDS=... or plate_diagnosis.py leave them), over the layouts
every directory has: Kendall tau of the area-weighted std (heated samples, lower face), the
median std of both tiers, and the RMS at the heated samples after removing each field's mean
(the shape error: what a std objective sees).

  python3 experiments/thermal/void_plane_ranking.py LABEL=FIELDS_DIR...
"""
import csv
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plate_diagnosis as d  # noqa: E402

S = d.samples()
subsets = {"heated": [i for i, q in enumerate(S) if q["heated"]],
           "lower": [i for i, q in enumerate(S) if q["face"] == "lower"]}


def field(path):
    return [float(r["T"]) for r in csv.DictReader(open(path))]


dirs = dict(a.split("=", 1) for a in sys.argv[1:])
names = None
for path in dirs.values():
    have = {f[:-8] for f in os.listdir(path) if f.endswith(".t2d.csv") and os.path.exists(os.path.join(path, f[:-8] + ".fd3.csv"))}
    names = have if names is None else names & have
names = sorted(names)
print(f"{len(names)} layouts: {' '.join(names)}")
print("tier,subset,tau_std,median_std_tier_k,median_std_t3_k,shape_rms_k")
for label, path in dirs.items():
    for sub, idx in subsets.items():
        w = [S[i]["w"] for i in idx]
        a, b, sq = [], [], 0.0
        for n in names:
            t2, t3 = field(os.path.join(path, n + ".t2d.csv")), field(os.path.join(path, n + ".fd3.csv"))
            (s2, m2), (s3, m3) = d.wstd([t2[i] for i in idx], w), d.wstd([t3[i] for i in idx], w)
            a.append(s2), b.append(s3)
            sq += sum(x * ((t2[i] - m2) - (t3[i] - m3)) ** 2 for i, x in zip(idx, w)) / sum(w)
        med = lambda v: sorted(v)[len(v) // 2]
        print(f"{label},{sub},{d.kendall(a, b):.3f},{med(a):.3f},{med(b):.3f},{(sq / len(names)) ** 0.5:.3f}")
