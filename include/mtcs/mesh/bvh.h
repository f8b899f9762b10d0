#pragma once
// Bounding-volume hierarchy over the triangles of a closed mesh, for the bore queries: the
// distance from a segment (a bore axis) to the surface, capped, and point containment.
//
// Flat arrays, leaves of up to 4 triangles, split at the median centroid along the longest
// axis of the node's centroid box (balanced depth, cheap to build; the surface-area heuristic
// is the mesh issue's to weigh).

#include <optional>
#include <vector>

#include "mtcs/mesh/triangle_mesh.h"

namespace mtcs::mesh {

class TriangleBvh {
 public:
  explicit TriangleBvh(const TriangleMesh& mesh);

  // Distance from the segment to the surface when it is below `cap`; otherwise some value
  // >= cap (the search stops there).
  double segment_distance(const Vec3& p0, const Vec3& p1, double cap) const;

  // Whether p lies inside the closed surface (parity of the crossings of a ray).
  bool contains(const Vec3& p) const;

  // The nearest crossing of the ray p + t d, t > 0: t and the triangle's unit normal.
  struct Hit {
    double t;
    Vec3 normal;
  };
  std::optional<Hit> first_hit(const Vec3& p, const Vec3& d) const;

  const Box& bounds() const { return nodes_.front().box; }
  std::size_t triangle_count() const { return tris_.size(); }

 private:
  struct Node {
    Box box;
    int first;  // leaf: first triangle; inner: index of the left child (right = first + 1)
    int count;  // leaf: number of triangles; inner: 0
  };
  void build(int node, int first, int count, std::vector<Vec3>& centroids);
  // Calls leaf(triangle) for every triangle in a leaf whose box the ray p + t d meets.
  template <class Leaf>
  void visit_ray(const Vec3& p, const Vec3& d, Leaf&& leaf) const;

  std::vector<Node> nodes_;
  std::vector<std::array<Vec3, 3>> tris_;
};

// Clearance of a solid cylinder from the solid bounded by the mesh, first version: the capsule
// around the cylinder (distance of the axis minus the radius), 0 when the axis touches or lies
// inside the solid. Never larger than the true distance: conservative by at most the radius at
// the bore's flat ends. Values >= cap are reported as cap.
double cylinder_clearance(const TriangleBvh& bvh, const Vec3& p0, const Vec3& p1, double radius, double cap);

}  // namespace mtcs::mesh
