#!/usr/bin/python3
"""Picture of a surface field written by mtcs (a cavity's temperature, say): the PLY that
`mtcs thermal --out field.ply` writes (vertex x y z, colour, value as quality), drawn in 3-D with
the same colour map and a colour bar in the field's unit.

Usage: plot_surface_field.py FIELD.ply OUT.png [TITLE]
"""
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.tri  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402


def read_ply(path):
    with open(path) as f:
        label, nv, nf = "value", 0, 0
        for line in f:
            words = line.split()
            if words[:2] == ["comment", "quality"]:
                label = line.split("=", 1)[1].split(",")[0].strip()
            elif words[:2] == ["element", "vertex"]:
                nv = int(words[2])
            elif words[:2] == ["element", "face"]:
                nf = int(words[2])
            elif words == ["end_header"]:
                break
        verts, values = [], []
        for _ in range(nv):
            w = f.readline().split()
            verts.append(tuple(float(x) for x in w[:3]))
            values.append(float(w[6]))
        faces = [tuple(int(x) for x in f.readline().split()[1:4]) for _ in range(nf)]
    return verts, values, faces, label


def facing_the_camera(verts, faces, elev, azim):
    """The faces whose outer side the camera sees. matplotlib sorts polygons by depth, one value
    each, and on a thin shell (a cup's two faces 2.5 mm apart) the far face shows through the near
    one in stripes; on a closed surface the faces turned away are hidden anyway. An open surface
    (no inside, no outside) keeps every face."""
    def normal(f):
        a, b, c = (verts[i] for i in f)
        u = [b[k] - a[k] for k in range(3)]
        v = [c[k] - a[k] for k in range(3)]
        return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
    # Six times the signed volume: its sign tells which side is out.
    volume = sum(sum(verts[f[0]][k] * n for k, n in enumerate(normal(f))) for f in faces)
    span = [max(v[k] for v in verts) - min(v[k] for v in verts) for k in range(3)]
    if abs(volume) <= 1e-6 * 6 * span[0] * span[1] * span[2]:
        return faces
    e, a = math.radians(elev), math.radians(azim)
    eye = (math.cos(e) * math.cos(a), math.cos(e) * math.sin(a), math.sin(e))
    out = 1 if volume > 0 else -1
    return [f for f in faces if out * sum(n * d for n, d in zip(normal(f), eye)) > 0]


def main(path, out, title=""):
    verts, values, faces, label = read_ply(path)
    lo, hi = min(values), max(values)
    cmap = plt.get_cmap("viridis")
    norm = matplotlib.colors.Normalize(lo, hi if hi > lo else lo + 1)
    xs, ys, zs = zip(*verts)
    extents = [max(c) - min(c) for c in (xs, ys, zs)]
    flat = [k for k in range(3) if extents[k] <= 1e-9 * max(extents)]
    if flat:  # a patch on a face: a plan view says more than a perspective
        a, b = [k for k in range(3) if k != flat[0]]
        coords = (xs, ys, zs)
        fig, ax = plt.subplots(figsize=(8, 6))
        tri = matplotlib.tri.Triangulation(coords[a], coords[b], faces)
        shaded = ax.tripcolor(tri, values, cmap=cmap, norm=norm, shading="gouraud")
        ax.set_aspect("equal")
        ax.set_xlabel("xyz"[a] + " (mm)")
        ax.set_ylabel("xyz"[b] + " (mm)")
        fig.colorbar(shaded, ax=ax, shrink=0.8).set_label(label)
        ax.set_title(title or f"{label}: {lo:.2f} to {hi:.2f}")
        fig.tight_layout()
        fig.savefig(out, dpi=110)
        return
    fig = plt.figure(figsize=(8, 6))
    ax = fig.add_subplot(projection="3d")
    faces = facing_the_camera(verts, faces, ax.elev, ax.azim)
    polys = [[verts[i] for i in f] for f in faces]
    colours = [cmap(norm(sum(values[i] for i in f) / 3)) for f in faces]
    # Edges in the faces' own colours: with none, antialiasing leaves light seams between them.
    ax.add_collection3d(Poly3DCollection(polys, facecolors=colours, edgecolors=colours, linewidths=0.2))
    span = max(max(xs) - min(xs), max(ys) - min(ys), max(zs) - min(zs)) / 2 or 1
    for axis, c in (("x", xs), ("y", ys), ("z", zs)):
        mid = (max(c) + min(c)) / 2
        getattr(ax, f"set_{axis}lim")(mid - span, mid + span)
        getattr(ax, f"set_{axis}label")(f"{axis} (mm)")
    ax.view_init(elev=35, azim=-60)
    bar = fig.colorbar(matplotlib.cm.ScalarMappable(norm=norm, cmap=cmap), ax=ax, shrink=0.7)
    bar.set_label(label)
    ax.set_title(title or f"{label}: {lo:.2f} to {hi:.2f}")
    fig.tight_layout()
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    main(*sys.argv[1:4])
