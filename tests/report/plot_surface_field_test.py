#!/usr/bin/python3
"""scripts/plot_surface_field.py on a part whose hot spot is inside (issue 45, item 10: the
picture showed only a lid's outside, the hot spot under it invisible): a closed hollow box (a lid
with its cavity sealed) whose hottest vertex lies on the inner face of its top. The sections must
pass through that vertex and cut both walls of the shell; the PNG is written with the 3-D view
and two sections.

Usage: plot_surface_field_test.py SCRIPTS_DIR SCRATCH_DIR
"""
import importlib.util
import math
import os
import sys


def hollow_box(outer, wall):
    """Vertices and outward faces of a closed shell: a box minus a smaller one (faces inward)."""
    verts, faces = [], []
    for lo, hi, flip in ((0.0, outer, False), (wall, outer - wall, True)):
        base = len(verts)
        for i in range(8):
            verts.append((hi if i & 1 else lo, hi if i & 2 else lo, hi if i & 4 else lo))
        quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
        for q in quads:
            for t in ((q[0], q[1], q[2]), (q[0], q[2], q[3])):
                t = (t[0], t[2], t[1]) if flip else t
                faces.append(tuple(base + k for k in t))
    return verts, faces


def write_ply(path, verts, values, faces):
    with open(path, "w") as f:
        f.write("ply\nformat ascii 1.0\ncomment quality = temperature [degC], per vertex\n")
        f.write(f"element vertex {len(verts)}\nproperty double x\nproperty double y\nproperty double z\n")
        f.write("property uchar red\nproperty uchar green\nproperty uchar blue\nproperty double quality\n")
        f.write(f"element face {len(faces)}\nproperty list uchar int vertex_indices\nend_header\n")
        for v, t in zip(verts, values):
            f.write(f"{v[0]} {v[1]} {v[2]} 0 0 0 {t}\n")
        for t in faces:
            f.write(f"3 {t[0]} {t[1]} {t[2]}\n")


def main(scripts, scratch):
    spec = importlib.util.spec_from_file_location("plot", os.path.join(scripts, "plot_surface_field.py"))
    plot = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(plot)
    verts, faces = hollow_box(40.0, 3.0)
    # Hottest at the inner box's corner (37, 37, 37): inside, hidden from every outside view.
    hot = (37.0, 37.0, 37.0)
    values = [100 - math.dist(v, hot) for v in verts]
    hottest = max(range(len(values)), key=lambda i: values[i])
    assert verts[hottest] == hot, verts[hottest]
    for axis in range(3):
        # The section the picture draws: through the hot corner itself, where the inner top face
        # lies in the plane of the z section.
        segments, seg_values = plot.section_through(verts, values, faces, axis, hot)
        assert segments, f"no section across {'xyz'[axis]}"
        a, b = [k for k in range(3) if k != axis]
        ends = [p for s in segments for p in s]
        # The cut passes through the hot corner: a segment ends within 1e-4 mm of it.
        assert min(math.hypot(p[0] - hot[a], p[1] - hot[b]) for p in ends) < 1e-4, axis
        # Both walls of the shell are cut: points at the outer (0 or 40) and the inner (3 or 37) faces.
        for wall in (0.0, 3.0, 37.0, 40.0):
            assert any(abs(p[0] - wall) < 1e-9 for p in ends), (axis, wall)
        # The section's values are those of the field there, interpolated along the cut edges.
        assert max(seg_values) <= max(values) + 1e-9 and min(seg_values) >= min(values) - 1e-9
    ply = os.path.join(scratch, "hollow.ply")
    png = os.path.join(scratch, "hollow.png")
    write_ply(ply, verts, values, faces)
    plot.main(ply, png, "hollow box")
    assert os.path.getsize(png) > 20000, os.path.getsize(png)
    figure = plot.plt.gcf()
    assert len([ax for ax in figure.axes if ax.get_label() != "<colorbar>"]) >= 3, figure.axes
    titles = [ax.get_title() for ax in figure.axes]
    assert sum("through the hottest point" in t for t in titles) == 2, titles
    print("ok: sections through the inner hot corner, picture", png)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
