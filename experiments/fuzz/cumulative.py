#!/usr/bin/env python3
"""Cumulative executions per fuzz target: the total before a round plus the round's lines.
  python3 experiments/fuzz/cumulative.py ROUND.tsv [SIDE_BY_SIDE.tsv]
ROUND.tsv: long_run.sh's lines (target, seconds, executions, exit code, tree); SIDE_BY_SIDE.tsv:
side_by_side.sh's (their executions count too: the same readers, the same sanitizer). Prints the
README's markdown table: this round, cumulative, left to 10 M and the time that takes at the
round's executions/s."""
import collections
import sys

# Cumulative executions until 2026-11-25 06:01 UTC (the README's tables before this round).
BEFORE = {"mold_spec": 53369, "layout": 769460, "pairs_csv": 1522217, "cylinders_csv": 1737831,
          "points_csv": 1995954, "front_file": 1492706, "mesh_stl": 384717, "mesh_off": 1991720,
          "mesh_obj": 2065307, "mesh_ply": 1521617, "run_store": 1298946}
GOAL = 10_000_000


def fmt(n):
    return "{:,}".format(int(n)).replace(",", " ")


execs, secs, exits = collections.Counter(), collections.Counter(), collections.defaultdict(list)
for line in open(sys.argv[1]):
    t, s, e, code = line.split("\t")[:4]
    execs[t] += int(e); secs[t] += int(s); exits[t].append(code)
side = collections.Counter()
if len(sys.argv) > 2:
    for line in open(sys.argv[2]):
        f = line.split("\t")
        if f[0] in BEFORE and f[3].isdigit(): side[f[0]] += int(f[3])
print("| target | this round: executions (seconds), executions/s | exit codes | side by side | cumulative | at 10 M? | left, at this round's rate |")
print("|---|---|---|---|---|---|---|")
total = 0
for t in BEFORE:
    cum = BEFORE[t] + execs[t] + side[t]
    total += cum
    rate = execs[t] / secs[t] if secs[t] else 0
    left = max(0, GOAL - cum)
    eta = "-" if not left else ("%.1f h" % (left / rate / 3600) if rate else "?")
    print("| %s | %s (%d s), %s | %s | %s | %s | %s | %s |" % (
        t, fmt(execs[t]), secs[t], fmt(rate), " ".join(exits[t]) or "-", fmt(side[t]), fmt(cum),
        "yes" if not left else "no", ("%s, %s" % (fmt(left), eta)) if left else "-"))
print("| all | %s (%d s) | | %s | %s | | |" % (fmt(sum(execs.values())), sum(secs.values()), fmt(sum(side.values())), fmt(total)))
