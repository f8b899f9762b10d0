"""The plate study's table from two sources, when the wall-distance arm is not rerun: the physics
rows of es_plate_physics_vs_distance.sh (OBJECTIVES=temperature_std), and the wall-distance rows
re-scored from their stored best layouts (es_plate_layouts/uniformity-SEED.layout.yaml, the runs
of the previous table: same seeds, budget and objective; `uniformity` does not depend on
thermal.objective_surface) from plate_diagnosis.py's per-sample solves in DIAG_DIR
(uniformity-SEED.fd3.csv, T3 at 3 mm; uniformity-SEED.t2d.csv when there), over the heated
surface, with the run's seconds and bores from the previous table.

  python3 experiments/thermal/plate_study_merge.py PHYSICS.csv DIAG_DIR PREVIOUS.csv OUT.csv
"""
import csv
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plate_diagnosis as d  # noqa: E402

physics, diag_dir, previous, out = sys.argv[1:5]
rows = list(csv.DictReader(open(physics)))
fields = list(rows[0])
old = {(r["objective"], r["seed"]): r for r in csv.DictReader(open(previous))}
samples = d.samples()
heated = [i for i, q in enumerate(samples) if q["heated"]]


def field(path):
    return [float(r["T"]) for r in csv.DictReader(open(path))] if os.path.exists(path) else None


for (objective, seed), o in sorted(old.items()):
    t3 = field(os.path.join(diag_dir, f"uniformity-{seed}.fd3.csv"))
    if objective != "uniformity" or t3 is None:
        continue
    t2 = field(os.path.join(diag_dir, f"uniformity-{seed}.t2d.csv"))
    w = [samples[i]["w"] for i in heated]
    std, mean = d.wstd([t3[i] for i in heated], w)
    rows.append({"objective": "uniformity", "seed": seed, "evaluations": o["evaluations"], "seconds": o["seconds"],
                 "surface": "heated", "t2d_std_k": "%.4f" % d.wstd([t2[i] for i in heated], w)[0] if t2 else "",
                 "t3_cell_mm": o["t3_cell_mm"], "t3_seconds": o["t3_seconds"], "t3_std_k": "%.4f" % std,
                 "t3_mean_c": "%.4f" % mean, "t3_max_c": "%.4f" % max(t3[i] for i in heated),
                 "t3_std_all_k": "%.4f" % d.wstd(t3, [q["w"] for q in samples])[0], "bores": o["bores"]})
rows.sort(key=lambda r: (int(r["seed"]), r["objective"] != "temperature_std"))
with open(out, "w") as f:
    w = csv.DictWriter(f, fieldnames=fields)
    w.writeheader()
    w.writerows(rows)
