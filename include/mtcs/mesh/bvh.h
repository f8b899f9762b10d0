#pragma once
// Bounding-volume hierarchy over the triangles of a closed mesh, for the bore queries: the
// exact distance from a solid cylinder (a bore) to the surface, capped by the clearance the
// caller needs, the distance from a segment, and point containment.
//
// Flat arrays, leaves of up to 4 triangles. Split rule: binned surface-area heuristic (16 bins
// along the longest axis of the node's centroid box), which minimises the expected number of
// nodes a query's bounds reach; the median split (balanced, cheaper to build) is kept for
// comparison. Measured with `mtcs bench clearance` (experiments/mesh/README.md): SAH queries
// are 7-25 % faster on five of the six meshes for 30-50 % more build time.

#include <limits>
#include <optional>
#include <vector>

#include "mtcs/geometry/cylinder_triangle_distance.h"
#include "mtcs/mesh/triangle_mesh.h"

namespace mtcs::mesh {

class TriangleBvh {
 public:
  enum class SplitRule { Median, SurfaceArea };
  explicit TriangleBvh(const TriangleMesh& mesh, SplitRule split_rule = SplitRule::SurfaceArea);

  // Distance from the segment to the surface when it is below `cap`; otherwise some value
  // >= cap (the search stops there).
  double segment_distance(const Vec3& p0, const Vec3& p1, double cap) const;

  // Distance from the solid cylinder to the surface (not the solid) when it is below `cap`;
  // otherwise `bounded` and a proven lower bound >= cap. Witnesses as in geometry::distance.
  // Thread-safe; allocates only to grow a per-thread search heap.
  geometry::TriangleDistanceResult cylinder_distance(const geometry::Cylinder& cylinder, double cap) const;

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
  void build(int node, int first, int count, int depth, std::vector<Vec3>& centroids);
  int sah_split(int first, int count, int axis, const Box& cbox, const std::vector<Vec3>& centroids) const;
  // Calls leaf(triangle) for every triangle in a leaf whose box the ray p + t d meets.
  template <class Leaf>
  void visit_ray(const Vec3& p, const Vec3& d, Leaf&& leaf) const;

  SplitRule split_rule_;
  std::vector<Node> nodes_;
  std::vector<std::array<Vec3, 3>> tris_;
  // Per triangle (same order): a bounding sphere, the cheapest distance bound at the leaves.
  struct Sphere {
    Vec3 center;
    double radius;
  };
  std::vector<Sphere> spheres_;
  std::vector<std::array<int, 3>> corners_;  // vertex indices, to know an edge met before
};

// Clearance of a solid cylinder from the solid bounded by a closed mesh: the exact distance to
// the surface, or 0 when the cylinder touches it or lies inside the solid ("buried": no surface
// within reach, but the axis midpoint is inside). With `upper_bound` (the clearance the caller
// needs) the search stops as soon as it is proved: `bounded` then means distance >= upper_bound.
struct Clearance {
  double distance = 0;
  bool bounded = false;
  bool buried = false;
  Vec3 on_cylinder = Vec3::Zero();  // witnesses, unspecified when bounded; the axis midpoint
  Vec3 on_surface = Vec3::Zero();   // twice when buried

  Vec3 where() const { return (on_cylinder + on_surface) / 2; }
};

Clearance cylinder_clearance(const TriangleBvh& bvh, const geometry::Cylinder& cylinder,
                             double upper_bound = std::numeric_limits<double>::infinity());

}  // namespace mtcs::mesh
