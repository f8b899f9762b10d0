#pragma once
// Area-weighted samples of the cavity surface, about one per sample_spacing^2 of area, for the
// thermal proxies. Structure of arrays, so that the distance loops vectorise.

#include <vector>

#include "mtcs/geometry/triangle_distance.h"
#include "mtcs/mesh/triangle_mesh.h"
#include "mtcs/mold/mold_spec.h"

namespace mtcs::eval {

struct SurfaceSamples {
  std::vector<double> x, y, z, weight;
  std::vector<geometry::Vec3> normal;  // unit, out of the part (into the steel); 0 on a patch
  std::size_t size() const { return x.size(); }
  double total_weight() const;
};

// A box: a grid on each face, cells at most `spacing` wide, one sample at each cell's centre.
SurfaceSamples sample_box(const geometry::Box& box, double spacing);
// A mesh: triangles subdivided finer than `spacing`, the pieces gathered into cubes of side
// `spacing`, one sample per cube at the piece nearest the cube's area-weighted centre; two where
// both faces of a wall thinner than the cube meet in it, one per face.
SurfaceSamples sample_mesh(const mesh::TriangleMesh& mesh, double spacing);
// A patch (a flat box on a block face): a grid of cells at most `spacing` wide on the
// rectangle, one sample at each cell's centre, the first in-plane axis (x, y, z order) fastest.
SurfaceSamples sample_patch(const geometry::Box& patch, double spacing);
// Whichever the cavity is, at its sample_spacing or at `spacing`.
SurfaceSamples sample_cavity(const mold::Cavity& cavity);
SurfaceSamples sample_cavity(const mold::Cavity& cavity, double spacing);

// The two in-plane axes of a flat box (x, y, z order) and its normal axis.
struct PatchAxes {
  int i, j, normal;
};
PatchAxes patch_axes(const geometry::Box& patch);

}  // namespace mtcs::eval
