#!/usr/bin/env python3
"""Writes the seed corpora of fuzz/corpus/<target>/ from the bundled molds and tests/data.

Seeds are small (the fuzzer mutates them; big seeds slow every execution). Run from anywhere:
python3 fuzz/make_corpus.py. Deterministic: same repo, same seeds.
"""
import pathlib
import sqlite3
import struct

ROOT = pathlib.Path(__file__).resolve().parent.parent
OUT = ROOT / "fuzz" / "corpus"


def put(target, name, data):
    d = OUT / target
    d.mkdir(parents=True, exist_ok=True)
    (d / name).write_bytes(data if isinstance(data, bytes) else data.encode())


def head(path, lines):
    return "".join(path.read_text().splitlines(keepends=True)[:lines])


def read_off(path):
    words = [w for line in path.read_text().splitlines() if not line.startswith("#") for w in line.split()]
    assert words[0] == "OFF"
    nv, nf = int(words[1]), int(words[2])
    at = 4
    verts = [tuple(float(w) for w in words[at + 3 * i: at + 3 * i + 3]) for i in range(nv)]
    at += 3 * nv
    faces = []
    for _ in range(nf):
        k = int(words[at])
        faces.append(tuple(int(w) for w in words[at + 1: at + 1 + k]))
        at += 1 + k
    return verts, faces


def triangles(verts, faces):
    for f in faces:
        for k in range(1, len(f) - 1):
            yield verts[f[0]], verts[f[k]], verts[f[k + 1]]


# The mold-spec target reads the meshes its specs name from a stand-in of molds/meshes/ (see
# fuzz/targets/mold_spec.cpp): the small meshes as they are, the big ones (the gear's 11 416
# triangles cost ~1 s an execution in the closed-mesh and self-intersection checks, the cup's 92
# still 8 ms) as a box of 12 triangles with the same bounds, so that every seed spec still
# passes the scene checks. Three broken boxes reach the refusals of a mesh that bounds no solid
# (the bundled meshes are all good ones), each named by a seed spec of its own.
def box_off(lo, hi, note, quads_of=lambda q: q, extra=()):
    corners = [(hi[0] if i & 1 else lo[0], hi[1] if i & 2 else lo[1], hi[2] if i & 4 else lo[2]) for i in range(8)]
    quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]  # outward
    tris = [t for a, b, c, d in quads_of(quads) for t in ((a, b, c), (a, c, d))]
    verts = corners + [v for box in extra for v in box[0]]
    tris += [tuple(8 + 8 * k + i for i in t) for k, box in enumerate(extra) for t in box[1]]
    text = "OFF\n# stand-in for the fuzzer: %s\n%d %d 0\n" % (note, len(verts), len(tris))
    text += "".join("%r %r %r\n" % tuple(v) for v in verts)
    return text + "".join("3 %d %d %d\n" % t for t in tris)


def write_stand_in_meshes(max_triangles=30):
    out = ROOT / "fuzz" / "mold_spec_meshes"
    out.mkdir(parents=True, exist_ok=True)
    for src in sorted((ROOT / "molds" / "meshes").glob("*.off")):
        verts, faces = read_off(src)
        if len(list(triangles(verts, faces))) <= max_triangles:
            (out / src.name).write_text(src.read_text())
            continue
        lo = [min(v[k] for v in verts) for k in range(3)]
        hi = [max(v[k] for v in verts) for k in range(3)]
        (out / src.name).write_text(box_off(lo, hi, "the bounds of molds/meshes/%s as a box" % src.name))
    lo, hi = [50.0, 50.0, 40.0], [170.0, 130.0, 80.0]  # the cup's bounds
    (out / "open_box.off").write_text(box_off(lo, hi, "a box without its top: not closed", lambda q: q[:1] + q[2:]))
    (out / "inward_box.off").write_text(
        box_off(lo, hi, "a box oriented inwards", lambda q: [tuple(reversed(x)) for x in q]))
    inner = box_off([60.0, 60.0, 30.0], [160.0, 140.0, 90.0], "")
    words = [w for line in inner.splitlines()[3:] for w in line.split()]
    inner_verts = [tuple(float(w) for w in words[3 * i: 3 * i + 3]) for i in range(8)]
    inner_tris = [tuple(int(w) for w in words[24 + 4 * i + 1: 24 + 4 * i + 4]) for i in range(12)]
    (out / "crossing_boxes.off").write_text(
        box_off(lo, hi, "two closed boxes through each other: self-intersecting", extra=[(inner_verts, inner_tris)]))


def put_stl(stem, tris):
    ascii_stl = "solid %s\n" % stem
    for a, b, c in tris:
        ascii_stl += " facet normal 0 0 0\n  outer loop\n"
        for v in (a, b, c):
            ascii_stl += "   vertex %r %r %r\n" % v
        ascii_stl += "  endloop\n endfacet\n"
    put("mesh_stl", stem + "_ascii.stl", ascii_stl + "endsolid %s\n" % stem)
    binary = bytearray(b"binary STL seed".ljust(80, b" ")) + struct.pack("<I", len(tris))
    for a, b, c in tris:
        binary += struct.pack("<12fH", 0, 0, 0, *a, *b, *c, 0)
    put("mesh_stl", stem + "_binary.stl", bytes(binary))


def main():
    write_stand_in_meshes()
    tetra = [(0.0, 0.0, 0.0), (10.0, 0.0, 0.0), (0.0, 10.0, 0.0), (0.0, 0.0, 10.0)]
    put_stl("tetrahedron", list(triangles(tetra, [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)])))
    for p in sorted((ROOT / "molds").glob("*.yaml")):
        (put("layout", p.name, p.read_text()) if p.name.endswith(".layout.yaml") else put("mold_spec", p.name, p.read_text()))
    cup = (ROOT / "molds" / "cup.yaml").read_text()
    for bad in ("open_box", "inward_box", "crossing_boxes"):
        put("mold_spec", "cup_%s.yaml" % bad, cup.replace("meshes/cup.off", "meshes/%s.off" % bad))
    for name in ("cylinder_pairs_exact.csv", "cylinder_pairs_public.csv"):
        put("pairs_csv", name, head(ROOT / "tests" / "data" / name, 6))
    for p in sorted((ROOT / "tests" / "data" / "mesh_clearance").glob("*.csv"))[:2]:
        put("cylinders_csv", p.name, head(p, 6))
    put("cylinders_csv", "plain.csv", "id,p0x,p0y,p0z,p1x,p1y,p1z,r\nb0,0,0,0,10,0,0,1\n# comment\nb1,1e-3,-2,3.5,4,5,6,0\n")
    put("points_csv", "points.csv", "x,y,z,T\n0,0,0,300\n1.5,-2,3e2,301\n\n0.25,1e-300,7,2\n")
    put("points_csv", "crlf.csv", "z,y,x\r\n1,2,3\r\n4,5,6\r\n")
    for p in sorted((ROOT / "tests" / "data" / "hv_fronts").glob("*_n10.txt")):
        put("front_file", p.name, p.read_text())

    for mesh in ("l_bracket.off", "cup.off"):
        src = ROOT / "molds" / "meshes" / mesh
        stem = src.stem
        put("mesh_off", mesh, src.read_text())
        verts, faces = read_off(src)
        # STL spells every corner out (the cup is 12 kB of ASCII, 1 ms an execution): the
        # l_bracket and a tetrahedron are enough to reach every branch of its reader.
        if stem == "l_bracket":
            put_stl(stem, list(triangles(verts, faces)))
        obj = "# %s\n" % stem + "".join("v %r %r %r\n" % v for v in verts)
        obj += "".join("f " + " ".join(str(i + 1) for i in f) + "\n" for f in faces)
        put("mesh_obj", stem + ".obj", obj)
        ply = ("ply\nformat ascii 1.0\nelement vertex %d\nproperty double x\nproperty double y\nproperty double z\n"
               "element face %d\nproperty list uchar int vertex_indices\nend_header\n" % (len(verts), len(faces)))
        ply += "".join("%r %r %r\n" % v for v in verts) + "".join("%d %s\n" % (len(f), " ".join(map(str, f))) for f in faces)
        put("mesh_ply", stem + ".ply", ply)
        bply = ("ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty float x\nproperty float y\n"
                "property float z\nelement face %d\nproperty list uchar int vertex_indices\nend_header\n"
                % (len(verts), len(faces))).encode()
        for v in verts:
            bply += struct.pack("<3f", *v)
        for f in faces:
            bply += struct.pack("<B%di" % len(f), len(f), *f)
        put("mesh_ply", stem + "_binary.ply", bply)

    # A run store with the schema of src/store/run_store.cpp and one generation of two.
    d = OUT / "run_store"
    d.mkdir(parents=True, exist_ok=True)
    path = d / "run.sqlite"
    path.unlink(missing_ok=True)
    db = sqlite3.connect(path)
    db.executescript(
        "CREATE TABLE meta(key TEXT PRIMARY KEY, value TEXT NOT NULL);"
        "CREATE TABLE generation(idx INTEGER PRIMARY KEY, evaluations INTEGER, best REAL,"
        "  feasible_share REAL, seconds REAL);"
        "CREATE TABLE individual(generation INTEGER, rank INTEGER, genotype BLOB, steps BLOB,"
        "  objectives BLOB, violation REAL, feasible INTEGER, value REAL, violations TEXT,"
        "  PRIMARY KEY(generation, rank));")
    db.executemany("INSERT INTO meta VALUES(?, ?)", [("program", "mtcs"), ("seed", "1"), ("algorithm", "es")])
    db.execute("INSERT INTO generation VALUES(0, 2, 1.5, 0.5, 0.25)")
    for rank in range(2):
        blob = struct.pack("<3d", 1.0 + rank, 2.0, 3.0)
        db.execute("INSERT INTO individual VALUES(0, ?, ?, ?, ?, ?, ?, ?, ?)",
                   (rank, blob, blob, struct.pack("<2d", 1.5, 2.5), 0.0 + rank, 1 - rank, 1.5 + rank, "" if rank == 0 else "bore_bore"))
    db.commit()
    db.close()


if __name__ == "__main__":
    main()
