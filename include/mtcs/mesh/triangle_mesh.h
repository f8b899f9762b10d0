#pragma once
// A triangle mesh as flat arrays: the form every mesh kernel reads. CGAL stays behind mesh_io.

#include <array>
#include <string>
#include <vector>

#include "mtcs/geometry/primitives.h"
#include "mtcs/geometry/triangle_distance.h"

namespace mtcs::mesh {

using geometry::Box;
using geometry::Vec3;

struct TriangleMesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 3>> triangles;  // counter-clockwise seen from outside

  const Vec3& corner(std::size_t t, int k) const { return vertices[std::size_t(triangles[t][k])]; }
  Box bounds() const;
  double area() const;
  double signed_volume() const;  // > 0 for a closed, outward-oriented surface
  void translate(const Vec3& offset);
};

// What is wrong with a mesh that must bound a solid, or "" when nothing is: non-finite
// coordinates, indices out of range, degenerate (zero-area) triangles, edges not shared by
// exactly two triangles in opposite directions (open, non-manifold or inconsistently oriented).
std::string closed_mesh_problem(const TriangleMesh& mesh);

// An axis-aligned box as a closed, outward-oriented mesh of 12 triangles.
TriangleMesh box_mesh(const Box& box);

}  // namespace mtcs::mesh
