"""The per-sample calibrations of void_plane.md: T2d corrected by one reference layout's T3 solve
(an offset T3_ref - T2d_ref, or a factor on the rise over the 40 degC coolant), each layout of
FIELDS_DIR (NAME.t2d.csv, NAME.fd3.csv) in turn the reference; Kendall tau of the heated std
against T3 over the others.

  python3 experiments/thermal/void_calibration.py FIELDS_DIR
"""
import csv, glob, os, sys, math, itertools
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plate_diagnosis as d
S = d.samples()
H = [i for i, q in enumerate(S) if q['heated']]
w = [S[i]['w'] for i in H]
def field(p): return [float(r['T']) for r in csv.DictReader(open(p))]
dirs = sys.argv[1:]
L = {}
for dd in dirs:
    for p in glob.glob(dd + '/*.t2d.csv'):
        name = os.path.basename(p)[:-8]
        f3 = glob.glob(dd + '/' + name + '.fd3.csv')
        if f3: L[dd.split('/')[-1] + ':' + name] = (field(p), field(f3[0]))
names = sorted(L)
print(len(names), 'layouts')
def std(t): return d.wstd([t[i] for i in H], w)[0]
t3 = [std(L[n][1]) for n in names]
t2 = [std(L[n][0]) for n in names]
print('none tau', round(d.kendall(t2, t3), 3))
Tc = 40
for kind in ('add', 'mul'):
    taus = []
    for r in names:
        a2, a3 = L[r]
        if kind == 'add': corr = lambda t: [t[i] + a3[i] - a2[i] for i in range(len(t))]
        else: corr = lambda t: [Tc + (t[i] - Tc) * (a3[i] - Tc) / (a2[i] - Tc) for i in range(len(t))]
        others = [n for n in names if n != r]
        taus.append(d.kendall([std(corr(L[n][0])) for n in others], [t3[names.index(n)] for n in others]))
    taus.sort()
    print(kind, 'tau over refs: median', round(taus[len(taus)//2], 3), 'range', round(taus[0], 3), round(taus[-1], 3))
