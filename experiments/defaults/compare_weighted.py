#!/usr/bin/env python3
"""Two CSVs of run.sh rows (before, after), per mold: reach (worst_covered <= 4 D), feasible,
>= 3 circuits, the weighted objective (sum of objective / the spec's scale, weights 1: the ES's
scalar) median and per seed, wins/losses of after against before, CPU seconds.
Usage: compare_weighted.py BEFORE.csv AFTER.csv"""
import csv, os, re, statistics, sys

here = os.path.dirname(os.path.abspath(__file__))


def spec_text(mold):
    for d in ("../../molds", "../../docs/first-mold", "."):
        p = os.path.join(here, d, mold)
        if os.path.exists(p):
            return open(p).read()
    raise SystemExit(f"no spec for {mold}")


def scales(mold):
    m = re.search(r"scales:\s*\{([^}]*)\}", spec_text(mold))
    return {k.strip(): float(v) for k, v in (kv.split(":") for kv in m.group(1).split(","))}


def largest_drill(mold):
    m = re.search(r"diameters:\s*\[([^\]]*)\]", spec_text(mold))
    return max(float(v) for v in m.group(1).split(","))


def weighted(row):
    s = scales(row["mold"])
    return sum(float(v) / s[k] for k, v in (kv.split("=") for kv in row["objectives"].split(";")))


def load(path):
    out = {}
    for r in csv.DictReader(open(path)):
        if r["algorithm"] == "es" and r["feasible"] in ("0", "1"):
            out.setdefault(r["mold"], {})[int(r["seed"])] = r
    return out


before, after = load(sys.argv[1]), load(sys.argv[2])
print("| mold | seeds | reach before -> after | feasible | >= 3 circuits | weighted median before -> after | after better / worse (seeds) | CPU s median before -> after |")
print("|---|---|---|---|---|---|---|---|")
for mold in after:
    seeds = sorted(set(after[mold]) & set(before.get(mold, {})))
    if not seeds:
        continue
    b, a = before[mold], after[mold]
    lim = 4 * largest_drill(mold)
    reach = lambda rs: sum(float(rs[s]["worst_covered_mm"]) <= lim for s in seeds)
    feas = lambda rs: sum(rs[s]["feasible"] == "1" for s in seeds)
    circ = lambda rs: sum(int(rs[s]["circuits"]) >= 3 for s in seeds)
    wb = [weighted(b[s]) for s in seeds]
    wa = [weighted(a[s]) for s in seeds]
    better = sum(x < y - 1e-9 for x, y in zip(wa, wb))
    worse = sum(x > y + 1e-9 for x, y in zip(wa, wb))
    cpu = lambda rs: statistics.median(float(rs[s]["cpu_s"]) for s in seeds)
    n = len(seeds)
    print(f"| {mold} | {n} | {reach(b)}/{n} -> {reach(a)}/{n} (<= {lim:g} mm) | {feas(b)}/{n} -> {feas(a)}/{n} | "
          f"{circ(b)}/{n} -> {circ(a)}/{n} | {statistics.median(wb):.3f} -> {statistics.median(wa):.3f} | "
          f"{better} / {worse} | {cpu(b):.1f} -> {cpu(a):.1f} |")
