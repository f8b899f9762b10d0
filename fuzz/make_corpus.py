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


def main():
    for p in sorted((ROOT / "molds").glob("*.yaml")):
        (put("layout", p.name, p.read_text()) if p.name.endswith(".layout.yaml") else put("mold_spec", p.name, p.read_text()))
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
        tris = list(triangles(verts, faces))
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
