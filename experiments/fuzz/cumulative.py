#!/usr/bin/env python3
"""Cumulative executions per fuzz target: the total before a round plus the round's lines.
  python3 experiments/fuzz/cumulative.py [--before 0601|0915|1036|1325] ROUND.tsv [OTHER.tsv...]
ROUND.tsv: long_run.sh's lines (target, seconds, executions, exit code, tree); OTHER.tsv: other
runs of the same readers, executions in the 4th column (side_by_side.sh's lines, smoke runs). Prints the
README's markdown table: this round, cumulative, left to 10 M and the time that takes at the
round's executions/s."""
import collections
import sys

# Cumulative executions before a round (the README's tables): until 2026-11-25 06:01 UTC, and
# until 09:15 UTC (the round of 08:11-09:15 and its side-by-side and smoke runs included).
ROUNDS = {"0601": {"mold_spec": 53369, "layout": 769460, "pairs_csv": 1522217, "cylinders_csv": 1737831,
          "points_csv": 1995954, "front_file": 1492706, "mesh_stl": 384717, "mesh_off": 1991720,
          "mesh_obj": 2065307, "mesh_ply": 1521617, "run_store": 1298946},
          "0915": {"mold_spec": 970220, "layout": 1647541, "pairs_csv": 2720737, "cylinders_csv": 3086947,
                   "points_csv": 3833007, "front_file": 2446798, "mesh_stl": 1596885, "mesh_off": 3317746,
                   "mesh_obj": 3764318, "mesh_ply": 3092947, "run_store": 2472620},
          # until 10:36 UTC (the round of 10:00-10:36 and CI's smoke run of 09:53 included)
          "1036": {"mold_spec": 976776, "layout": 1681932, "pairs_csv": 5086166, "cylinders_csv": 5075541,
                   "points_csv": 10827485, "front_file": 3204510, "mesh_stl": 1608646, "mesh_off": 6813115,
                   "mesh_obj": 9136185, "mesh_ply": 6662006, "run_store": 2497102},
          # until 13:25 UTC (the rounds d and e of 11:00-13:25; smoke runs since 10:36 not added)
          "1325": {"mold_spec": 1997387, "layout": 4394513, "pairs_csv": 9048476, "cylinders_csv": 11261915,
                   "points_csv": 10827485, "front_file": 13591036, "mesh_stl": 9088593, "mesh_off": 10244370,
                   "mesh_obj": 10798031, "mesh_ply": 10015833, "run_store": 9911128}}
args = sys.argv[1:]
BEFORE = ROUNDS["0601"]
if args[:1] == ["--before"]:
    BEFORE, args = ROUNDS[args[1]], args[2:]
GOAL = 10_000_000
# Executions/s of the UBSan round of 05:43-06:01 (load ~2): the estimate for a target this round
# did not run.
EARLIER_RATE = {"pairs_csv": 12281, "cylinders_csv": 14008, "points_csv": 17057, "front_file": 12509,
                "mesh_off": 7980, "mesh_obj": 9683, "mesh_ply": 7386, "run_store": 5254}


def fmt(n):
    return "{:,}".format(int(n)).replace(",", " ")


execs, secs, exits = collections.Counter(), collections.Counter(), collections.defaultdict(list)
for line in open(args[0]):
    t, s, e, code = line.split("\t")[:4]
    execs[t] += int(e); secs[t] += int(s); exits[t].append(code)
side = collections.Counter()
for other in args[1:]:
    for line in open(other):
        f = line.rstrip("\n").split("\t")
        if f[0] in BEFORE and f[3].isdigit(): side[f[0]] += int(f[3])
print("| target | this round: executions (seconds), executions/s | exit codes | other runs (side by side, smoke) | cumulative | at 10 M? | left, at this round's rate |")
print("|---|---|---|---|---|---|---|")
total = 0
for t in BEFORE:
    cum = BEFORE[t] + execs[t] + side[t]
    total += cum
    rate = execs[t] / secs[t] if secs[t] else EARLIER_RATE.get(t, 0)
    left = max(0, GOAL - cum)
    eta = "-" if not left else ("%.1f h" % (left / rate / 3600) + ("" if secs[t] else " at 05:43's rate") if rate else "?")
    run = "%s (%d s), %s" % (fmt(execs[t]), secs[t], fmt(rate)) if secs[t] else "not run"
    print("| %s | %s | %s | %s | %s | %s | %s |" % (
        t, run, " ".join(exits[t]) or "-", fmt(side[t]), fmt(cum),
        "yes" if not left else "no", ("%s, %s" % (fmt(left), eta)) if left else "-"))
print("| all | %s (%d s) | | %s | %s | | |" % (fmt(sum(execs.values())), sum(secs.values()), fmt(sum(side.values())), fmt(total)))
