#!/usr/bin/python3
"""Picture of a surface field written by mtcs (a cavity's temperature, say): the PLY that
`mtcs thermal --out field.ply` writes (vertex x y z, colour, value as quality), drawn in 3-D with
the same colour map and a colour bar in the field's unit, beside two sections through the
hottest point: a hot spot inside a part (a lid's core, a boss) shows there even where the 3-D
view sees only the outside. The hottest point is marked in every panel.

Usage: plot_surface_field.py FIELD.ply OUT.png [TITLE]
"""
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.collections  # noqa: E402
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


def section(verts, values, faces, axis, at):
    """The surface cut by the plane coordinate[axis] = at: segments ((p, q) in the plane's other
    two coordinates) and each segment's mean value, interpolated along the cut edges."""
    a, b = [k for k in range(3) if k != axis]
    segments, seg_values = [], []
    for f in faces:
        side = [verts[i][axis] - at for i in f]
        cut = []
        for j in range(3):
            i0, i1 = f[j], f[(j + 1) % 3]
            s0, s1 = side[j], side[(j + 1) % 3]
            if (s0 < 0) != (s1 < 0):
                t = s0 / (s0 - s1)
                p = [verts[i0][k] + t * (verts[i1][k] - verts[i0][k]) for k in range(3)]
                cut.append(((p[a], p[b]), values[i0] + t * (values[i1] - values[i0])))
        if len(cut) == 2:
            segments.append((cut[0][0], cut[1][0]))
            seg_values.append((cut[0][1] + cut[1][1]) / 2)
    return segments, seg_values


def section_through(verts, values, faces, axis, point):
    """The section through `point`, its plane moved a millionth of the part's size to the side
    whose cut passes nearest the point: a face lying in the plane itself (the hot spot on a face
    across the axis) adds no segment, the faces just beside it are cut."""
    span = max(v[axis] for v in verts) - min(v[axis] for v in verts)
    a, b = [k for k in range(3) if k != axis]

    def miss(cut):  # how far the cut's nearest end lies from the point, in the plane
        return min((math.hypot(p[0] - point[a], p[1] - point[b]) for s in cut[0] for p in s), default=math.inf)
    cuts = [section(verts, values, faces, axis, point[axis] + side * 1e-6 * span) for side in (-1, 1)]
    return min(cuts, key=miss)


def draw_section(ax, verts, values, faces, axis, hot, norm, cmap, label):
    a, b = [k for k in range(3) if k != axis]
    segments, seg_values = section_through(verts, values, faces, axis, hot)
    lines = matplotlib.collections.LineCollection(segments, colors=[cmap(norm(v)) for v in seg_values], linewidths=2.2)
    ax.add_collection(lines)
    coords = list(zip(*verts))
    pad = 0.05 * max(max(coords[a]) - min(coords[a]), max(coords[b]) - min(coords[b]))
    ax.set_xlim(min(coords[a]) - pad, max(coords[a]) + pad)
    ax.set_ylim(min(coords[b]) - pad, max(coords[b]) + pad)
    ax.set_aspect("equal")
    ax.plot([hot[a]], [hot[b]], marker="*", color="red", markersize=14, markeredgecolor="white", zorder=5)
    ax.set_xlabel("xyz"[a] + " (mm)")
    ax.set_ylabel("xyz"[b] + " (mm)")
    ax.set_title(f"section at {'xyz'[axis]} = {hot[axis]:.1f} mm through the hottest point", fontsize=9)


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
    hottest = max(range(len(values)), key=lambda i: values[i])
    hot = verts[hottest]
    # The sections cut across the part's two longest extents: through a shell they show its wall
    # profile, with the core's or the boss's inside.
    longest = sorted(range(3), key=lambda k: -extents[k])[:2]
    fig = plt.figure(figsize=(14, 6))
    grid = fig.add_gridspec(2, 2, width_ratios=[1.5, 1])
    ax = fig.add_subplot(grid[:, 0], projection="3d")
    ax.view_init(elev=35, azim=-60)
    for row, axis in enumerate(longest):
        draw_section(fig.add_subplot(grid[row, 1]), verts, values, faces, axis, hot, norm, cmap, label)
    all_faces = faces
    faces = facing_the_camera(verts, all_faces, ax.elev, ax.azim)
    polys = [[verts[i] for i in f] for f in faces]
    colours = [cmap(norm(sum(values[i] for i in f) / 3)) for f in faces]
    # Edges in the faces' own colours: with none, antialiasing leaves light seams between them.
    ax.add_collection3d(Poly3DCollection(polys, facecolors=colours, edgecolors=colours, linewidths=0.2))
    span = max(max(xs) - min(xs), max(ys) - min(ys), max(zs) - min(zs)) / 2 or 1
    for axis, c in (("x", xs), ("y", ys), ("z", zs)):
        mid = (max(c) + min(c)) / 2
        getattr(ax, f"set_{axis}lim")(mid - span, mid + span)
        getattr(ax, f"set_{axis}label")(f"{axis} (mm)")
    # The hottest point, a star drawn over the surface even where the surface hides it (inside
    # a lid, on a core): the sections show where it lies.
    ax.computed_zorder = False  # drawn in the order added
    ax.scatter([hot[0]], [hot[1]], [hot[2]], marker="*", s=260, color="red", edgecolors="white", depthshade=False, zorder=10)
    unit = label[label.find("[") + 1:label.find("]")] if "[" in label and "]" in label else ""
    ax.text2D(0.02, 0.02, f"hottest {hi:.1f} {unit} at ({hot[0]:.1f}, {hot[1]:.1f}, {hot[2]:.1f}) mm (the star; the sections cut through it)",
              transform=ax.transAxes, fontsize=9, color="darkred")
    bar = fig.colorbar(matplotlib.cm.ScalarMappable(norm=norm, cmap=cmap), ax=ax, shrink=0.7, pad=0.08)
    bar.set_label(label)
    ax.set_title(title or f"{label}: {lo:.2f} to {hi:.2f}")
    fig.tight_layout()
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    main(*sys.argv[1:4])
