#!/usr/bin/env python3
"""One CSV row per seed from the run folders of run.sh: mold, algorithm, seed, feasible,
circuits and bores of the best layout, the objectives, front size and hypervolume (SMS-EMOA),
warnings, CPU seconds."""
import json, os, re, sys

mold, algo, work, seeds = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
for s in range(1, seeds + 1):
    d = os.path.join(work, f"seed{s}")
    try:
        j = json.load(open(os.path.join(d, "summary.json")))
    except Exception as e:  # a run that failed: say why
        err = open(d + ".err").read().strip().splitlines()
        print(f"{os.path.basename(mold)},{algo},{s},error,,,,,,,,\"{err[-1] if err else e}\",")
        continue
    layout = open(os.path.join(d, "best.layout.yaml")).read()
    circuits = layout.count("diameter:")
    bores = sum(1 for _ in open(os.path.join(d, "bores.csv"))) - 1
    o = j.get("objectives", {})
    vals = ";".join(f"{k}={v:.4g}" for k, v in o.items())
    # distinct designs on the front
    front = ""
    if algo == "sms-emoa" and os.path.exists(os.path.join(d, "front.csv")):
        rows = open(os.path.join(d, "front.csv")).read().strip().splitlines()[1:]
        # distinct designs: objective vectors that differ after rounding to 0.01 (mm, K, cost units)
        front = str(len({tuple(round(float(v), 2) for v in r.split(",")) for r in rows}))
    cpu = open(d + ".cpu").read().strip().splitlines()[-1]
    warnings = " | ".join(j.get("warnings", []))
    print(f"{os.path.basename(mold)},{algo},{s},{int(j['feasible'])},{circuits},{bores},"
          f"{o.get('worst_covered', '')},{vals},{j.get('front_size', '')},{front},{j.get('hypervolume', '')},"
          f"\"{warnings}\",{cpu}")
