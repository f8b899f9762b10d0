#pragma once
// Component-vs-component interference (Song, Park and Chung, "Web-based interference
// verification system for injection mold design"): the triangle pairs two meshes share, found
// by descending two bounding-volume hierarchies together down to the exact triangle test, with
// a touching tolerance, a nesting check and the distance when they are apart.

#include <cstddef>
#include <vector>

#include "mtcs/mesh/mesh_parts.h"
#include "mtcs/mesh/triangle_intersection.h"
#include "mtcs/mesh/triangle_mesh.h"

namespace mtcs::mesh {

// An axis-aligned box hierarchy over the triangles of one mesh, in flat arrays, leaves of up
// to 4 triangles, with each triangle's box and normal stored in leaf order.
//   kMedian: split at the median triangle centroid along the longest axis (balanced).
//   kSolidFace: the paper's order: split between solids first, then between whole faces
//     (ordered by centroid, about half the triangles each side), then at the median triangle.
// Both find the same pairs at about the same speed; kMedian builds faster and stays balanced,
// so it is the default (experiments/mesh/interference.md).
class InterferenceBvh {
 public:
  enum class Split { kMedian, kSolidFace };
  InterferenceBvh(const TriangleMesh& mesh, MeshParts parts, Split split = Split::kMedian);

  struct Node {
    Box box;
    int child;       // index of the left child (right = child + 1); -1 for a leaf
    int begin, end;  // the node's triangles: positions [begin, end) of the leaf order
  };
  const std::vector<Node>& nodes() const { return nodes_; }
  int triangle_at(int position) const { return order_[std::size_t(position)]; }  // mesh index
  const Triangle& triangle(int position) const { return tris_[std::size_t(position)]; }
  const Box& triangle_box(int position) const { return boxes_[std::size_t(position)]; }
  const Vec3& normal(int position) const { return normals_[std::size_t(position)]; }  // not unit
  const std::array<int, 3>& corners(int position) const { return ids_[std::size_t(position)]; }
  const MeshParts& parts() const { return parts_; }
  std::size_t size() const { return tris_.size(); }

  // Whether p lies inside the closed surface (parity of a ray's crossings).
  bool contains(const Vec3& p) const;

 private:
  void build(int node, int begin, int end, Split split, std::vector<Vec3>& centroids);
  int split_groups(int begin, int end, const std::vector<int>& key, std::vector<Vec3>& centroids);
  int split_median(int begin, int end, std::vector<Vec3>& centroids);

  std::vector<Node> nodes_;
  std::vector<int> order_;              // leaf order -> mesh triangle
  std::vector<Triangle> tris_;          // in leaf order
  std::vector<Box> boxes_;              // the triangles' boxes, in leaf order
  std::vector<Vec3> normals_;           // (b - a) x (c - a), in leaf order
  std::vector<std::array<int, 3>> ids_; // vertex indices, in leaf order
  MeshParts parts_;                     // indexed by mesh triangle
};

struct InterferencePair {
  int a, b;  // triangle indices in mesh A and mesh B
  TriangleIntersection x;
  bool penetrating = true;  // still intersecting with both surfaces moved in by half the tolerance
};

struct InterferenceStats {
  std::size_t node_pairs = 0;      // box pairs tested
  std::size_t triangle_tests = 0;  // exact triangle-triangle tests
};

// All intersecting triangle pairs, ordered by (a, b).
std::vector<InterferencePair> intersecting_pairs(const InterferenceBvh& a, const InterferenceBvh& b,
                                                 InterferenceStats* stats = nullptr);

// Triangle pairs of one mesh that intersect without sharing a corner, ordered.
std::vector<std::array<int, 2>> self_intersections(const InterferenceBvh& bvh, InterferenceStats* stats = nullptr);

// Distance between the two surfaces (0 when they meet), pruned by box distances.
double surface_distance(const InterferenceBvh& a, const InterferenceBvh& b, InterferenceStats* stats = nullptr);

// The mesh moved inward (against its outward normals) by `offset`: every vertex moves so that
// the planes of its incident triangles move by `offset` (least squares over their distinct
// normals: exact where up to three planar faces meet, as at the corners of CAD parts; close on
// curved surfaces; the move is capped at 3 offset at sharp tips).
TriangleMesh shrunk(const TriangleMesh& mesh, double offset);

struct InterferenceReport {
  std::vector<InterferencePair> pairs;  // every intersecting pair, touching ones included
  std::size_t penetrating = 0;          // pairs still intersecting after the shrink
  std::vector<int> solids_of_a_inside_b, solids_of_b_inside_a;  // nested without surface contact
  bool interferes = false;              // a penetrating pair or a nested solid
  double distance = 0;                  // between the surfaces when no pair intersects, else 0
  InterferenceStats stats;
};

// The component check of A and B as placed. Surfaces in contact are not interference unless
// the solids overlap by more than touch_tolerance: both meshes are shrunk by half of it (see
// shrunk) and the shrunk surfaces must still cross, or a shrunk solid lie inside the other.
// With a tolerance of 0 every intersecting pair counts. The hierarchies use `split`.
InterferenceReport interfere(const TriangleMesh& a, const TriangleMesh& b, double touch_tolerance,
                             InterferenceBvh::Split split = InterferenceBvh::Split::kMedian);

}  // namespace mtcs::mesh
