#!/usr/bin/python3
"""Geometry for the FreeFem++ reference of the coupled cavity condition (numpy only).

  model.py check PROBLEM.json CHANNELS.csv            clearances of the channels (>= 3 mm)
  model.py build PROBLEM.json CHANNELS.csv H HB OUT   surface mesh OUT.mesh (medit) + OUT.par
  model.py collect MOLD DIR OUT.csv                   convergence table, CSV of the finest P2

Labels of the surface mesh: block faces 1..6 (-x,+x,-y,+y,-z,+z), cavity 10, channel i 100+i.
H: target edge (mm) on the cavity and the bores; HB: on the block faces (tetgen grades between).
"""
import json
import sys

import numpy as np

FACES = ["-x", "+x", "-y", "+y", "-z", "+z"]


def load(problem, channels):
    P = json.load(open(problem))
    C = np.array([t["corners"] for t in P["cavity"]], float)  # (n,3,3), CCW seen from the part
    ch = np.loadtxt(channels, delimiter=",", skiprows=1, ndmin=2)
    return P, C, ch


def point_tri_dist(p, T):
    """Distance from points p (m,3) to each triangle of T (n,3,3): (m,n). Ericson's closest point."""
    a, b, c = T[:, 0][None], T[:, 1][None], T[:, 2][None]
    p = p[:, None, :]
    ab, ac, ap = b - a, c - a, p - a
    d1, d2 = (ab * ap).sum(-1), (ac * ap).sum(-1)
    bp = p - b
    d3, d4 = (ab * bp).sum(-1), (ac * bp).sum(-1)
    cp = p - c
    d5, d6 = (ab * cp).sum(-1), (ac * cp).sum(-1)
    va, vb, vc = d3 * d6 - d5 * d4, d5 * d2 - d1 * d6, d1 * d4 - d3 * d2
    den = va + vb + vc
    den = np.where(den == 0, 1e-300, den)
    v, w = vb / den, vc / den
    q = a + ab * v[..., None] + ac * w[..., None]  # interior
    # edge / vertex regions, applied in reverse priority
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.clip(d1 / (d1 - d3), 0, 1)
        m = (vc <= 0) & (d1 >= 0) & (d3 <= 0)
        q = np.where(m[..., None], a + ab * t[..., None], q)
        t = np.clip(d2 / (d2 - d6), 0, 1)
        m = (vb <= 0) & (d2 >= 0) & (d6 <= 0)
        q = np.where(m[..., None], a + ac * t[..., None], q)
        t = np.clip((d4 - d3) / ((d4 - d3) + (d5 - d6)), 0, 1)
        m = (va <= 0) & ((d4 - d3) >= 0) & ((d5 - d6) >= 0)
        q = np.where(m[..., None], b + (c - b) * t[..., None], q)
    q = np.where(((d1 <= 0) & (d2 <= 0))[..., None], a, q)
    q = np.where(((d3 >= 0) & (d4 <= d3))[..., None], b, q)
    q = np.where(((d6 >= 0) & (d5 <= d6))[..., None], c, q)
    return np.linalg.norm(p - q, axis=-1)


def min_dist(p, T, chunk=200):
    """Per point: min distance to the triangles and the index of the nearest one."""
    d, i = np.empty(len(p)), np.empty(len(p), int)
    for s in range(0, len(p), chunk):
        D = point_tri_dist(p[s:s + chunk], T)
        i[s:s + chunk] = D.argmin(1)
        d[s:s + chunk] = D.min(1)
    return d, i


def winding(p, T):
    """Generalised winding number of the closed surface T at points p (-1 inside: T is CW outward)."""
    out = np.empty(len(p))
    for k, q in enumerate(p):
        a, b, c = T[:, 0] - q, T[:, 1] - q, T[:, 2] - q
        la, lb, lc = (np.linalg.norm(v, axis=1) for v in (a, b, c))
        num = np.einsum("ij,ij->i", a, np.cross(b, c))
        den = (la * lb * lc + np.einsum("ij,ij->i", a, b) * lc + np.einsum("ij,ij->i", b, c) * la
               + np.einsum("ij,ij->i", c, a) * lb)
        out[k] = np.arctan2(num, den).sum() / (2 * np.pi)
    return out


def seg_seg(p0, p1, q0, q1, n=2000):
    """Distance between two segments (dense sampling; error < length/n)."""
    s = np.linspace(0, 1, n)[:, None]
    A, B = p0 + s * (p1 - p0), q0 + s * (q1 - q0)
    return min(np.linalg.norm(A[:, None] - B[None], axis=-1).min(), 1e9)


def check(problem, channels):
    """Steel between each bore and the cavity, the other bores and the block faces (capsule bound)."""
    P, C, ch = load(problem, channels)
    lo, hi = np.array(P["block"]["min"]), np.array(P["block"]["max"])
    ok = True
    for i, c in enumerate(ch):
        p0, p1, r = c[0:3], c[3:6], c[6]
        axis = (p1 - p0) / np.linalg.norm(p1 - p0)
        s = np.linspace(0, 1, int(np.linalg.norm(p1 - p0) / 0.05) + 2)[:, None]
        d, _ = min_dist(p0 + s * (p1 - p0), C)
        cav = d.min() - r  # capsule around the axis: a lower bound for the flat-capped cylinder
        # extent of the flat-capped cylinder along each axis: end points +- r * sqrt(1 - a_k^2)
        ext = r * np.sqrt(np.clip(1 - axis ** 2, 0, 1))
        face = min((np.minimum(p0, p1) - ext - lo).min(), (hi - np.maximum(p0, p1) - ext).min())
        other = min([seg_seg(p0, p1, q[0:3], q[3:6]) - r - q[6] for j, q in enumerate(ch) if j != i])
        inside = winding(np.array([(p0 + p1) / 2]), C)[0]
        flag = cav >= 3 and face >= 3 and other >= 3 and abs(inside) < 0.5
        ok &= flag
        print(f"channel {i}: steel to cavity >= {cav:.2f} mm, to faces {face:.2f} mm, "
              f"to other bores >= {other:.2f} mm {'OK' if flag else 'VIOLATION'}")
    return ok


# ---------------------------------------------------------------- surface mesh
class Surf:
    def __init__(self):
        self.V, self.key, self.T = [], {}, []

    def v(self, x):
        k = tuple(np.round(x, 7))
        if k not in self.key:
            self.key[k] = len(self.V)
            self.V.append(np.array(x, float))
        return self.key[k]

    def tri(self, a, b, c, lab):
        self.T.append((self.v(a), self.v(b), self.v(c), lab))


def refine(C, h):
    """Conforming longest-edge bisection of a closed triangle mesh until every edge <= h."""
    V, inv = np.unique(C.reshape(-1, 3).round(7), axis=0, return_inverse=True)
    V = [v for v in V]
    F = [list(f) for f in inv.reshape(-1, 3)]
    import heapq
    edges = {}  # (i,j) sorted -> set of faces

    def add(fi):
        f = F[fi]
        for k in range(3):
            e = tuple(sorted((f[k], f[(k + 1) % 3])))
            edges.setdefault(e, set()).add(fi)
            L = np.linalg.norm(V[e[0]] - V[e[1]])
            if L > h:
                heapq.heappush(heap, (-L, e))

    heap = []
    for fi in range(len(F)):
        add(fi)
    while heap:
        _, e = heapq.heappop(heap)
        if e not in edges:
            continue
        fs = list(edges.pop(e))
        m = len(V)
        V.append((V[e[0]] + V[e[1]]) / 2)
        for fi in fs:
            f = F[fi]
            for k in range(3):  # drop this face's edges from the map
                ee = tuple(sorted((f[k], f[(k + 1) % 3])))
                if ee in edges:
                    edges[ee].discard(fi)
            k = [t for t in range(3) if {f[t], f[(t + 1) % 3]} == set(e)][0]
            a, b, c = f[k], f[(k + 1) % 3], f[(k + 2) % 3]  # edge a-b split at m, opposite c
            F[fi] = [a, m, c]
            F.append([m, b, c])
            add(fi)
            add(len(F) - 1)
    V = np.array(V)
    return V[np.array(F)]


def cylinder(S, p0, p1, r, h, lab):
    """Closed cylinder (lateral + flat caps), normals outward of the cylinder (into the bore)."""
    ax = p1 - p0
    L = np.linalg.norm(ax)
    ax = ax / L
    u = np.cross(ax, [1, 0, 0] if abs(ax[0]) < 0.9 else [0, 1, 0])
    u /= np.linalg.norm(u)
    w = np.cross(ax, u)
    nt = max(12, int(np.ceil(2 * np.pi * r / h)))
    nz = max(1, int(np.ceil(L / h)))
    ang = 2 * np.pi * np.arange(nt) / nt
    ring = lambda c, rr, n, off=0.0: [c + rr * (np.cos(2 * np.pi * (j + off) / n) * u +
                                                 np.sin(2 * np.pi * (j + off) / n) * w) for j in range(n)]
    for k in range(nz):
        A, B = ring(p0 + ax * L * k / nz, r, nt), ring(p0 + ax * L * (k + 1) / nz, r, nt)
        for j in range(nt):
            jn = (j + 1) % nt
            S.tri(A[j], A[jn], B[jn], lab)
            S.tri(A[j], B[jn], B[j], lab)
    nr = max(1, int(np.ceil(r / h)))
    for cen, sgn in ((p0, -1), (p1, 1)):  # caps: concentric rings zipped together
        rings = [[cen]] + [ring(cen, r * q / nr, nt if q == nr else max(6, round(nt * q / nr)))
                           for q in range(1, nr + 1)]
        for q in range(1, nr + 1):
            inner, outer = rings[q - 1], rings[q]
            ai = [2 * np.pi * j / len(inner) for j in range(len(inner))] if q > 1 else [0.0]
            ao = [2 * np.pi * j / len(outer) for j in range(len(outer))]
            if q == 1:
                for j in range(len(outer)):
                    t = (inner[0], outer[j], outer[(j + 1) % len(outer)])
                    S.tri(*(t if sgn > 0 else t[::-1]), lab)
                continue
            i = o = 0
            ni, no = len(inner), len(outer)
            while i < ni or o < no:  # advance the ring whose next vertex has the smaller angle
                ai_next = ai[i + 1] if i + 1 < ni else 2 * np.pi
                ao_next = ao[o + 1] if o + 1 < no else 2 * np.pi
                if o < no and (i >= ni or ao_next <= ai_next):
                    t = (inner[i % ni], outer[o % no], outer[(o + 1) % no])
                    o += 1
                else:
                    t = (inner[i % ni], outer[o % no], inner[(i + 1) % ni])
                    i += 1
                S.tri(*(t if sgn > 0 else t[::-1]), lab)


def block(S, lo, hi, hb):
    n = [max(2, int(np.ceil((hi[k] - lo[k]) / hb))) for k in range(3)]
    for f, name in enumerate(FACES):
        k = "xyz".index(name[1])
        a, b = [j for j in range(3) if j != k]
        g = np.zeros(3)
        g[k] = lo[k] if name[0] == "-" else hi[k]
        for i in range(n[a]):
            for j in range(n[b]):
                def P(ii, jj):
                    x = g.copy()
                    x[a] = lo[a] + (hi[a] - lo[a]) * ii / n[a]
                    x[b] = lo[b] + (hi[b] - lo[b]) * jj / n[b]
                    return x
                S.tri(P(i, j), P(i + 1, j), P(i + 1, j + 1), f + 1)
                S.tri(P(i, j), P(i + 1, j + 1), P(i, j + 1), f + 1)


def build(problem, channels, h, hb, out):
    P, C, ch = load(problem, channels)
    lo, hi = np.array(P["block"]["min"]), np.array(P["block"]["max"])
    S = Surf()
    block(S, lo, hi, hb)
    R = refine(C, h)
    for t in R:
        S.tri(t[0], t[1], t[2], 10)
    for i, c in enumerate(ch):
        cylinder(S, c[0:3], c[3:6], c[6], h, 101 + i)
    V = np.array(S.V)
    with open(out + ".mesh", "w") as f:
        f.write(f"MeshVersionFormatted 2\nDimension 3\nVertices\n{len(V)}\n")
        f.writelines(f"{x:.9g} {y:.9g} {z:.9g} 0\n" for x, y, z in V)
        f.write(f"Triangles\n{len(S.T)}\n")
        f.writelines(f"{a + 1} {b + 1} {c + 1} {l}\n" for a, b, c, l in S.T)
        f.write("End\n")
    # a hole point inside the part: candidates = centroids pushed inward, keep the deepest inside
    n = np.cross(C[:, 1] - C[:, 0], C[:, 2] - C[:, 0])
    n /= np.linalg.norm(n, axis=1)[:, None]  # right-hand normal: into the part
    cen = C.mean(1)
    rng = np.random.default_rng(1)
    pick = rng.choice(len(C), min(len(C), 200), replace=False)
    cand = np.concatenate([cen[pick] + d * n[pick] for d in (0.3, 0.8, 1.2, 2, 4, 8)])
    inside = winding(cand, C) < -0.5
    dist, _ = min_dist(cand[inside], C)
    assert len(dist), "no point inside the part found"
    hole, depth = cand[inside][dist.argmax()], dist.max()
    holes = [hole] + [(c[0:3] + c[3:6]) / 2 for c in ch]
    # sample points moved 0.01 mm into the steel along the nearest cavity triangle's normal
    Sm = np.array(P["samples"], float)
    _, near = min_dist(Sm, C)
    moved = Sm - 0.01 * n[near]
    w = winding(moved, C)
    assert np.all(w > -0.5), f"{(w <= -0.5).sum()} moved samples inside the part"
    hp = P["cavity"][0]["film"]
    assert all(t["film"] == hp and t["flux"] == 0 for t in P["cavity"]), "non-uniform cavity"
    Tp = P["cavity"][0]["part_temperature"]
    fc = {f["face"]: f for f in P["faces"]}
    with open(out + ".par", "w") as f:  # plain numbers read by solve.edp
        f.write(f"{P['conductivity']} {hp} {Tp}\n")
        f.write(" ".join(f"{fc[nm]['film']} {fc[nm]['ambient']}" for nm in FACES) + "\n")
        f.write(f"{len(holes)}\n" + "".join(f"{x:.6f} {y:.6f} {z:.6f}\n" for x, y, z in holes))
        f.write(f"{len(ch)}\n" + "".join(f"{c[7]} {c[8]}\n" for c in ch))
        f.write(f"{len(moved)}\n" + "".join(f"{x:.9f} {y:.9f} {z:.9f}\n" for x, y, z in moved))
    print(f"{out}.mesh: {len(V)} vertices, {len(S.T)} triangles (cavity {len(R)}), "
          f"hole point {np.round(hole, 3)} depth {depth:.2f} mm")


def collect(mold, d, out):
    """Convergence of FreeFem's own runs at the samples; the finest P2 goes to OUT."""
    P = json.load(open(f"{d}/{mold}_problem.json"))
    S = np.array(P["samples"], float)
    runs = {}
    for lev in ("coarse", "fine"):
        for el in ("P1", "P2"):
            try:
                runs[(lev, el)] = np.loadtxt(f"{d}/{mold}_{lev}_{el}.T")
            except OSError:
                pass
    # reference: the finest P2 run (without any P2, the finest P1)
    best = next(k for k in (("fine", "P2"), ("coarse", "P2"), ("fine", "P1")) if k in runs)
    ref = runs[best]
    print(f"{mold}: {len(S)} samples, reference {best[0]} {best[1]}: min {ref.min():.3f} mean "
          f"{ref.mean():.3f} max {ref.max():.3f} degC")
    r = " ".join(best)
    print(f"| run | RMS vs {r} (K) | max vs {r} (K) | mean (degC) |\n|---|---|---|---|")
    for k, T in runs.items():
        dd = T - ref
        print(f"| {k[0]} {k[1]} | {np.sqrt((dd ** 2).mean()):.4f} | {np.abs(dd).max():.4f} | "
              f"{T.mean():.4f} |")
    with open(out, "w") as f:
        f.write("x,y,z,T\n")
        f.writelines(f"{x:.6f},{y:.6f},{z:.6f},{t:.6f}\n" for (x, y, z), t in zip(S, ref))


if __name__ == "__main__":
    a = sys.argv
    if a[1] == "check":
        sys.exit(0 if check(a[2], a[3]) else 1)
    elif a[1] == "build":
        build(a[2], a[3], float(a[4]), float(a[5]), a[6])
    elif a[1] == "collect":
        collect(a[2], a[3], a[4])
