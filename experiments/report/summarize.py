#!/usr/bin/env python3
"""Median and max per page of a side_by_side.sh CSV. Usage: summarize.py FILE.csv"""
import csv, statistics, sys
from collections import defaultdict
rows = defaultdict(list)
for r in csv.DictReader(open(sys.argv[1])):
    rows[r['page']].append(r)
print(f"{'page':<16}{'n':>3}{'load':>12}{'wall med':>10}{'wall max':>10}{'clock med':>10}{'clock max':>10}{'1st frame med':>14}")
for page, rs in rows.items():
    w = [float(r['load_to_drawn_s']) for r in rs]; c = [float(r['page_clock_s']) for r in rs]
    f = [float(r['first_frame_s']) for r in rs]; l = [float(r['load1']) for r in rs]
    print(f"{page:<16}{len(rs):>3}{min(l):>6.1f}-{max(l):<5.1f}{statistics.median(w):>10.2f}{max(w):>10.2f}"
          f"{statistics.median(c):>10.2f}{max(c):>10.2f}{statistics.median(f):>14.2f}")
