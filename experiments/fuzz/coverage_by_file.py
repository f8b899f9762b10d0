#!/usr/bin/env python3
# Covered edges per source file of two libFuzzer replays with -print_coverage=1 (old, new):
#   python3 experiments/fuzz/coverage_by_file.py OLD.txt NEW.txt
# mtcs files of src/mold, src/io, src/mesh by name; the rest (CGAL, yaml-cpp headers, std) as other.
import re, sys, collections
def load(p):
    d = collections.Counter(); tot = collections.Counter()
    for line in open(p):
        m = re.match(r'(UN)?COVERED_FUNC: hits: \d+ edges: (\d+)/(\d+) .* (\S+):\d+$', line.strip())
        if not m: continue
        f = re.sub(r'^.*?/src/', 'src/', m.group(4)); f = re.sub(r'^.*/include/', 'include/', f)
        key = f if f.startswith(('src/mold', 'src/io', 'src/mesh')) else ('CGAL' if 'CGAL' in f else 'other')
        d[key] += int(m.group(2)); tot[key] += int(m.group(3))
    return d, tot
o, ot = load(sys.argv[1]); n, nt = load(sys.argv[2])
for k in sorted(set(o) | set(n), key=lambda k: -max(o[k], n[k])):
    if o[k] or n[k]: print("%-40s old %5d  new %5d  (of %d)" % (k, o[k], n[k], nt[k]))
print("%-40s old %5d  new %5d" % ("all", sum(o.values()), sum(n.values())))
