#pragma once
// A scalar field on a surface (a temperature per vertex, say), for the viewers people use:
// VTK PolyData (.vtp, ParaView) and PLY with per-vertex colours and quality (MeshLab).

#include <array>
#include <ostream>
#include <string>
#include <vector>

#include "mtcs/mesh/triangle_mesh.h"

namespace mtcs::mesh {

struct SurfaceField {
  TriangleMesh surface;
  std::vector<double> values;  // one per vertex
  std::string name;            // e.g. "temperature"
  std::string unit;            // e.g. "degC"
};

// The mesh with its triangles bisected at their longest edges until no edge is longer than
// max_edge (or than the mesh's longest edge / max_split): a field sampled at the vertices then
// follows its variation on large flat faces, while small triangles (a thin wall's rim) stay as
// they are. Both triangles of an edge split it at the same point, so a closed mesh stays closed.
TriangleMesh refine(const TriangleMesh& mesh, double max_edge, int max_split = 64);

// VTK XML PolyData, ASCII, the field as point data (ParaView opens it directly).
void write_vtp(std::ostream& out, const SurfaceField& field);

// ASCII PLY with per-vertex colours from a perceptual colour map over [lo, hi] and the value as
// vertex quality (MeshLab shows both).
void write_ply(std::ostream& out, const SurfaceField& field, double lo, double hi);

// The colour map (viridis-like, dark blue -> yellow) at t in [0, 1].
std::array<unsigned char, 3> color_map(double t);

}  // namespace mtcs::mesh
