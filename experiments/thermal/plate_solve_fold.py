import sys, collections, re
root = sys.argv[2] if len(sys.argv) > 2 else 'LineSinkModel::solve+'
blocks = open(sys.argv[1]).read().split('\n\n')
tot = 0; under = collections.Counter(); leaf = collections.Counter(); pair = collections.Counter()
def short(s):
    s = s.strip().split(' ', 1)[1] if ' ' in s.strip() else s
    s = re.sub(r'\+0x[0-9a-f]+ \(.*', '', s)
    s = re.sub(r'\(.*', '', s)
    return s[-60:]
for b in blocks:
    fr = [l.strip() for l in b.strip().split('\n')[1:] if l.strip()]
    if not fr: continue
    tot += 1
    idx = [i for i, f in enumerate(fr) if root in f]
    if not idx: continue
    i = idx[-1]
    child = short(fr[i-1]) if i > 0 else '(self)'
    # second level below child
    under[child] += 1
    leaf[short(fr[0])] += 1
    pair[(child, short(fr[0]))] += 1
n = sum(under.values())
print('total', tot, 'under', root, n)
for k, v in under.most_common(25): print(f'{v:6d} {100*v/n:5.1f}% {k}')
print('--- leaf')
for k, v in leaf.most_common(25): print(f'{v:6d} {100*v/n:5.1f}% {k}')
print('--- child/leaf')
for k, v in pair.most_common(30): print(f'{v:6d} {100*v/n:5.1f}% {k}')
