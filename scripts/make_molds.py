#!/usr/bin/env python3
"""Generates the procedural mold scenes in molds/: spec (NAME.yaml), reference layout
(NAME.layout.yaml) and part meshes (molds/meshes/NAME.off).

Parts are unions of axis-aligned boxes, meshed exactly: the grid of all box bounds, a quad on
every cell face between an inside and an outside cell, oriented outwards, vertices shared. The
result is closed, manifold (no two boxes touch only along an edge) and outward-oriented.

Usage: python3 scripts/make_molds.py [OUT_DIR]   (default: molds)
"""
import itertools
import math
import os
import sys


def union_mesh(boxes):
    """Triangle mesh (vertices, triangles) of the union of boxes ((x0,y0,z0), (x1,y1,z1))."""
    axes = [sorted({b[s][k] for b in boxes for s in (0, 1)}) for k in range(3)]
    n = [len(a) - 1 for a in axes]

    def inside(i, j, k):
        if not (0 <= i < n[0] and 0 <= j < n[1] and 0 <= k < n[2]):
            return False
        c = [(axes[0][i] + axes[0][i + 1]) / 2, (axes[1][j] + axes[1][j + 1]) / 2,
             (axes[2][k] + axes[2][k + 1]) / 2]
        return any(all(b[0][d] < c[d] < b[1][d] for d in range(3)) for b in boxes)

    cells = {(i, j, k): inside(i, j, k) for i in range(n[0]) for j in range(n[1]) for k in range(n[2])}
    index = {}
    vertices, triangles = [], []

    def vid(g):
        if g not in index:
            index[g] = len(vertices)
            vertices.append(tuple(axes[d][g[d]] for d in range(3)))
        return index[g]

    for (i, j, k), full in cells.items():
        if not full:
            continue
        for d in range(3):
            for side in (0, 1):
                nb = [i, j, k]
                nb[d] += 1 if side else -1
                if cells.get(tuple(nb), False):
                    continue
                # The face of cell (i,j,k) at coordinate index g[d] = cell[d] + side.
                e1, e2 = (d + 1) % 3, (d + 2) % 3
                base = [i, j, k]
                base[d] += side
                corners = []
                for a, b in ((0, 0), (1, 0), (1, 1), (0, 1)):
                    g = list(base)
                    g[e1] += a
                    g[e2] += b
                    corners.append(vid(tuple(g)))
                # (e1, e2, d) is right-handed: counter-clockwise seen from +d.
                if not side:
                    corners.reverse()
                triangles.append((corners[0], corners[1], corners[2]))
                triangles.append((corners[0], corners[2], corners[3]))
    return vertices, triangles


def write_off(path, mesh):
    vertices, triangles = mesh
    with open(path, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(vertices), len(triangles)))
        for v in vertices:
            f.write("%.17g %.17g %.17g\n" % v)
        for t in triangles:
            f.write("3 %d %d %d\n" % t)


def fmt(v):
    return "[" + ", ".join("%g" % x for x in v) + "]"


def write_layout(path, circuits, note):
    with open(path, "w") as f:
        f.write("# %s\n# Hand-made reference layout: circuits of waypoints, inlet first, outlet last (mm).\n" % note)
        f.write("circuits:\n")
        for diameter, points in circuits:
            f.write("  - diameter: %g\n    waypoints:\n" % diameter)
            for p in points:
                f.write("      - %s\n" % fmt(p))


def u_loop(x0, x1, y_far, z, y_port=0.0):
    """A U-shaped circuit: in at the -y face at x0, along y to y_far, across to x1, back out.

    Without plugs inside a hole, a serpentine's inner cross holes would cut its own legs; U
    loops side by side, their cross holes drilled from the nearer side face, cut nothing."""
    return [(x0, y_port, z), (x0, y_far, z), (x1, y_far, z), (x1, y_port, z)]


def shift(points, o):
    return [tuple(p[k] + o[k] for k in range(3)) for p in points]


def physics(thickness, extra="", temperatures=True):
    """The thermal section and the temperature objectives of a part of ABS with this wall
    thickness (mm). The cavity is coupled to the part (docs/thermal-model.md): the part gives heat
    to the steel only while the steel is colder, through a film derived from the polymer, the wall
    and the cycle; the cooling time is an outcome, so cycle_time is an objective and no layout
    scores better by letting the mold run hotter."""
    alpha, melt, eject, coolant = 0.095, 230.0, 90.0, 40.0
    cooling = thickness ** 2 / (math.pi ** 2 * alpha) * math.log(4 / math.pi * (melt - coolant) / (eject - coolant))
    section = ("# ABS, %g mm walls: the part (230 C melt, ejected at 90 C) coupled to the steel; a %.1f s\n"
               "# cooling time with the wall at the coolant; 8 l/min of water at 40 C per circuit.\n"
               "thermal:\n"
               "  steel_conductivity: 30\n"
               "  coolant: {temperature: 40, flow_rate: 8}\n"
               "  ambient: {temperature: 25, film: 10}\n"
               "  cavity_condition: coupled\n"
               "  cycle: {fill: 1, pack: 3, open: 5}\n%s"
               "  tier: t2d\n"
               % (thickness, cooling, extra))
    use = ("  use: [temperature_std, cycle_time, cost]\n" if temperatures else
           "  use: [uniformity, worst_covered, cost]\n")
    return (section + "objectives:\n" + use +
            "  # 1 s of cycle weighs as 1 K of spread over the cavity and 1 000 of drilling cost.\n"
            "  scales: {uniformity: 5, worst_covered: 20, cost: 1000, temperature_mean: 10, temperature_std: 1,\n"
            "           temperature_max: 10, cycle_time: 1}\n")


def void_surface(panel):
    """The line sinks' view of the part's void: an insulating surface of panels this wide (mm);
    the width per mold from experiments/thermal/void_surface.md (ranking against the finite
    volumes, cost per new bore)."""
    return ("# The part's void as a surface of %g mm panels taking the part's heat: on random layouts\n"
            "# the line sinks then rank as the finite volumes do (experiments/thermal/void_surface.md).\n"
            "  cavity_void: surface\n"
            "  void_panel: %g\n" % (panel, panel))


TIER0 = """objectives:
  use: [uniformity, worst_covered, cost]
  scales: {uniformity: 5, worst_covered: 20, cost: 1000}
"""


def main(out):
    meshes = os.path.join(out, "meshes")
    os.makedirs(meshes, exist_ok=True)

    # Flat plate: a primitive box cavity (no mesh code runs), four ejector pins.
    pins = "".join(
        "  - {name: ejector%d, cylinder: {p0: %s, p1: %s, radius: 3}, clearance: 3}\n"
        % (i, fmt((x, y, 0)), fmt((x, y, 105)), ) for i, (x, y) in enumerate([(60, 35), (240, 35), (60, 165), (240, 165)]))
    # The part's top face gives its heat to the other mold half (its own cooling, not modelled:
    # no bore fits in the 12 mm above the cavity), so no flux above z = 107.
    top = ("# No flux into the 12 mm of steel above the cavity (no bore fits there): the part's top face\n"
           "# gives its heat to the other mold half, with a cooling of its own (not modelled).\n"
           "  regions: [{box: {min: [0, 0, 107], max: [300, 200, 120]}, heat_flux: 0}]\n"
           "# The temperature objectives over samples 11 mm apart (332 heated, not the cavity's 1 166):\n"
           "# an ES child costs less than half; std within 0.06 K on ES results, the ranking against\n"
           "# T3 unchanged (experiments/thermal/plate_samples.md).\n"
           "  sample_spacing: 11\n")
    with open(os.path.join(out, "plate.yaml"), "w") as f:
        f.write((PLATE % pins).replace("{physics}", physics(3, top + void_surface(12))))
    # The same plate scored by wall distances (tier 0): ~50x faster, for comparisons and for the
    # tests that optimise.
    with open(os.path.join(out, "plate_wall_distance.yaml"), "w") as f:
        f.write("# molds/plate.yaml with the wall-distance objectives (tier 0) instead of temperatures.\n"
                + (PLATE % pins).replace("{physics}", TIER0))
    write_layout(os.path.join(out, "plate.layout.yaml"),
                 [(8, u_loop(70, 100, 150, 88)), (8, u_loop(135, 165, 180, 88)), (8, u_loop(200, 230, 150, 88))],
                 "plate: three U loops 13 mm of steel under the plate")

    # Rectangular cup, 2.5 mm walls, open at +z.
    ox, oy, oz, w = (50, 50, 40), (170, 130, 80), 0, 2.5
    cup = [((50, 50, 40), (170, 130, 42.5)),          # floor
           ((50, 50, 42.5), (52.5, 130, 80)), ((167.5, 50, 42.5), (170, 130, 80)),
           ((52.5, 50, 42.5), (167.5, 52.5, 80)), ((52.5, 127.5, 42.5), (167.5, 130, 80))]
    write_off(os.path.join(meshes, "cup.off"), union_mesh(cup))
    with open(os.path.join(out, "cup.yaml"), "w") as f:
        f.write(CUP.replace("{physics}", physics(2.5, extra=void_surface(12))))
    write_layout(os.path.join(out, "cup.layout.yaml"),
                 [(8, u_loop(70, 100, 115, 24)), (8, u_loop(120, 150, 115, 24)),
                  (8, u_loop(30, 190, 150, 60))],
                 "cup: two U loops under the floor, one around the walls")

    # L-bracket: inner-corner hot spot.
    bracket = [((60, 40, 40), (180, 140, 46)), ((60, 40, 46), (66, 140, 120))]
    write_off(os.path.join(meshes, "l_bracket.off"), union_mesh(bracket))
    with open(os.path.join(out, "l_bracket.yaml"), "w") as f:
        f.write(BRACKET.replace("{physics}", physics(6, extra=void_surface(12))))
    write_layout(os.path.join(out, "l_bracket.layout.yaml"),
                 [(8, u_loop(80, 110, 125, 26)), (8, u_loop(130, 160, 125, 26)),
                  (8, u_loop(44, 24, 125, 90))],
                 "l_bracket: two U loops under the base, one behind the upright")

    # Ribbed box with a deep boss.
    ribbed = cup + [((52.5, 88.75, 42.5), (167.5, 91.25, 70)),   # long rib
                    ((108.75, 52.5, 42.5), (111.25, 88.75, 70)),  # cross rib
                    ((130, 100, 42.5), (145, 115, 78))]           # deep boss
    write_off(os.path.join(meshes, "ribbed_box.off"), union_mesh(ribbed))
    with open(os.path.join(out, "ribbed_box.yaml"), "w") as f:
        f.write(RIBBED.replace("{physics}", physics(2.5, extra=void_surface(12))))
    write_layout(os.path.join(out, "ribbed_box.layout.yaml"),
                 [(8, u_loop(70, 100, 115, 24)), (8, u_loop(120, 150, 115, 24))],
                 "ribbed_box: the floor only; the boss stays hot (no baffle or bubbler here)")

    # A real part: the herringbone gear of molds/meshes (LGPL-2.1, see molds/meshes/LICENSE.md).
    with open(os.path.join(out, "gear.yaml"), "w") as f:
        f.write(GEAR.replace("{physics}", physics(5, extra=void_surface(8))))
    write_layout(os.path.join(out, "gear.layout.yaml"),
                 [(8, u_loop(55, 85, 125, 25)), (8, u_loop(100, 130, 125, 25)),
                  (8, [(160, 50, 56), (132, 50, 56), (132, 110, 56), (160, 110, 56)])],
                 "gear: two U loops under the gear, one beside its rim entered from +x")

    # Extreme: 1 mm wall, a forest of ejector pins, 4 mm bores, coordinates offset by 1e4.
    o = (1e4, 1e4, 1e4)
    pins = "".join(
        "  - {name: pin%d, cylinder: {p0: %s, p1: %s, radius: 1.5}, clearance: 2}\n"
        % (i, fmt(shift([(x, y, 0)], o)[0]), fmt(shift([(x, y, 60)], o)[0]))
        for i, (x, y) in enumerate(itertools.product(range(36, 170, 20), range(28, 130, 20))))
    with open(os.path.join(out, "extreme.yaml"), "w") as f:
        f.write(EXTREME % (fmt(o), fmt(shift([(200, 150, 80)], o)[0]), fmt(shift([(30, 20, 60)], o)[0]),
                           fmt(shift([(170, 130, 61)], o)[0]), pins))
    write_layout(os.path.join(out, "extreme.layout.yaml"),
                 [(4, shift(u_loop(46, 66, 138, 49), o)), (4, shift(u_loop(86, 106, 146, 49), o)),
                  (4, shift(u_loop(126, 146, 138, 49), o))],
                 "extreme: 4 mm bores threading between the pins, 9 mm under a 1 mm wall")

    # The thermal reference block (tests/data/thermal/block3d_case.txt): a heated patch on the
    # top face, bores drilled straight through along x (one circuit per bore: inlet at x = 0,
    # outlet at x = 120, the same y and z).
    with open(os.path.join(out, "thermal_block.yaml"), "w") as f:
        f.write(THERMAL_BLOCK)
    write_layout(os.path.join(out, "thermal_block.layout.yaml"),
                 [(d, [(0, y, z), (120, y, z)]) for y, z, d in [(20, 45, 10), (40, 47, 8), (61, 43, 10)]],
                 "thermal_block: the reference case's bores B1, B2, B3, straight through along x")


PLATE = """# Flat plate 200 x 150 x 3 mm in a 300 x 200 x 120 mm block: a primitive cavity, so no mesh
# code runs. Generated by scripts/make_molds.py; docs/mold-spec.md documents every field.
units: mm
block: {box: {min: [0, 0, 0], max: [300, 200, 120]}}
cavity:
  box: {min: [50, 25, 105], max: [250, 175, 108]}
  sample_spacing: 5.5
  wall_thickness: 3
  parting: {core: +z, at: 108}  # opens along z at the top face (the core's; no heat enters it)
keep_outs:
%sdrilling:
  diameters: [6, 8, 10]
  axis_parallel: true
  allowed_faces: [+x, -x, +y, -y]
  max_depth_ratio: 50
  tip_angle_deg: 118
clearances: {bore_bore: 4, bore_cavity: 1.0D, bore_surface: 3}
circuits: {min: 1, max: 4, waypoints: [2, 12], inlet_faces: [-y], outlet_faces: [-y]}
{physics}  target_wall_distance: 2.0D
  cost: {setup: 20, per_mm: 0.05, deep_factor: 0.02, plug: 5}
penalty: {variant: constrained_domination, power: 2, weight: 1}
"""

CUP = """# Rectangular cup, 120 x 80 x 40 mm, 2.5 mm walls, open at +z, in a 220 x 180 x 120 mm block.
# Generated by scripts/make_molds.py.
units: mm
block: {box: {min: [0, 0, 0], max: [220, 180, 120]}}
cavity:
  mesh: meshes/cup.off
  sample_spacing: 4
  wall_thickness: local  # from the mesh: each place its own wall, corners and bosses thicker
  parting: {core: +z, at: 80}  # opens along z at the rim: the core half forms the inside
drilling:
  diameters: [8, 10]
  axis_parallel: true
  allowed_faces: [+x, -x, +y, -y]
  baffles: {faces: [+z], max: 2}  # blind bores down into the core, with a baffle or a bubbler
clearances: {bore_bore: 4, bore_cavity: 1.0D, bore_surface: 3}
circuits: {min: 1, max: 4, waypoints: [2, 14], inlet_faces: [-y], outlet_faces: [-y]}
{physics}"""

BRACKET = """# L-bracket: a 6 mm base and a 6 mm upright; the inner corner is the hot spot.
# Generated by scripts/make_molds.py.
units: mm
block: {box: {min: [0, 0, 0], max: [240, 180, 160]}}
cavity:
  mesh: meshes/l_bracket.off
  sample_spacing: 4
  wall_thickness: local  # from the mesh: each place its own wall, corners and bosses thicker
drilling:
  diameters: [8, 10]
  axis_parallel: true
  allowed_faces: [+x, -x, +y, -y]
clearances: {bore_bore: 4, bore_cavity: 1.0D, bore_surface: 3}
circuits: {min: 1, max: 4, waypoints: [2, 14], inlet_faces: [-y, -x], outlet_faces: [-y, -x]}
{physics}"""

RIBBED = """# Ribbed box: the cup with two ribs and a deep boss (38 mm tall).
# Generated by scripts/make_molds.py.
units: mm
block: {box: {min: [0, 0, 0], max: [220, 180, 120]}}
cavity:
  mesh: meshes/ribbed_box.off
  sample_spacing: 4
  wall_thickness: local  # from the mesh: each place its own wall, corners and bosses thicker
  parting: {core: +z, at: 80}  # opens along z at the rim: the core half forms the inside
drilling:
  diameters: [6, 8]
  axis_parallel: true
  allowed_faces: [+x, -x, +y, -y]
  max_depth_ratio: 40
  baffles: {faces: [+z], max: 2}  # blind bores down into the core, with a baffle or a bubbler
clearances: {bore_bore: 4, bore_cavity: 1.0D, bore_surface: 3}
circuits: {min: 1, max: 4, waypoints: [2, 14], inlet_faces: [-y], outlet_faces: [-y]}
{physics}"""

GEAR = """# A real part: the herringbone gear (74 x 74 x 22 mm, 11 416 triangles) of molds/meshes,
# centred at (80, 80, 56) in a 160 x 160 x 90 mm block. Generated by scripts/make_molds.py.
units: mm
block: {box: {min: [0, 0, 0], max: [160, 160, 90]}}
cavity:
  mesh: meshes/mcad_herringbone_gear.off
  translate: [80, 80, 55]
  sample_spacing: 3
  wall_thickness: 5
drilling:
  diameters: [6, 8]
  axis_parallel: true
  allowed_faces: [+x, -x, +y, -y]
clearances: {bore_bore: 4, bore_cavity: 1.0D, bore_surface: 3}
circuits: {min: 1, max: 4, waypoints: [2, 12], inlet_faces: [-y, +x], outlet_faces: [-y, +x]}
{physics}"""

EXTREME = """# Extreme scene: a 1 mm wall, a forest of ejector pins, 4 mm bores, coordinates offset by 1e4 mm.
# Generated by scripts/make_molds.py.
units: mm
block: {box: {min: %s, max: %s}}
cavity:
  box: {min: %s, max: %s}
  sample_spacing: 3
  wall_thickness: 1
keep_outs:
%sdrilling:
  diameters: [4, 6]
  axis_parallel: true
  allowed_faces: [+x, -x, +y, -y]
  max_depth_ratio: 60
clearances: {bore_bore: 2, bore_cavity: 2.0D, bore_surface: 2}
circuits: {min: 1, max: 6, waypoints: [2, 20], inlet_faces: [-y], outlet_faces: [-y]}
objectives:
  use: [uniformity, worst_covered, cost]
  scales: {uniformity: 2, worst_covered: 10, cost: 1000}
"""

THERMAL_BLOCK = """# The thermal reference block (tests/data/thermal/block3d_case.txt): a 120 x 80 x 60 mm steel
# block heated through a 60 x 48 mm patch on its top face (50 kW/m^2: 144 W), every other face
# convective (10 W/(m^2 K) to 25 C), bore walls at the coolant, 40 C (Dirichlet). Bores run
# straight through along x: one circuit per bore, inlet at x = 0, outlet at x = 120.
# Generated by scripts/make_molds.py; docs/mold-spec.md documents every field.
units: mm
block: {box: {min: [0, 0, 0], max: [120, 80, 60]}}
cavity:
  patch: {face: +z, min: [30, 16], max: [90, 64]}
  sample_spacing: 2
  wall_thickness: 2.5
drilling:
  diameters: [6, 8, 10, 12]
  axis_parallel: true
  allowed_faces: [-x, +x]
  max_depth_ratio: 50
  tip_angle_deg: 118
clearances: {bore_bore: 3, bore_cavity: 3, bore_surface: 3}
circuits: {min: 2, max: 5, waypoints: [2, 2], inlet_faces: [-x], outlet_faces: [+x]}
thermal:
  steel_conductivity: 30
  coolant: {temperature: 40}
  ambient: {temperature: 25, film: 10}
  heat_flux: 50000
  tier: t2d
objectives:
  use: [temperature_std, temperature_max, cost]
  scales: {uniformity: 5, worst_covered: 20, cost: 1000, temperature_mean: 10, temperature_std: 1,
           temperature_max: 10, cycle_time: 10}
  cost: {setup: 20, per_mm: 0.05, deep_factor: 0.02, plug: 5}
penalty: {variant: constrained_domination, power: 2, weight: 1}
"""

if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "molds")
