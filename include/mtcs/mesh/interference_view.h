#pragma once
// An interference report as the designer looks at it (the source paper's view): the pairs
// grouped by solid and face of each component, and both meshes in one PLY with the triangles
// coloured by what they do.

#include <ostream>
#include <vector>

#include "mtcs/mesh/interference.h"
#include "mtcs/mesh/mesh_parts.h"

namespace mtcs::mesh {

struct FaceGroup {
  int solid_a = 0, face_a = 0, solid_b = 0, face_b = 0;
  int pairs = 0, penetrating = 0;
  double depth = 0;  // mm, measure_overlap_depths
};

// One group per (solid, face) of A x (solid, face) of B that has intersecting pairs, ordered by
// those four indices, each with its overlap depth (below; `mb` as placed).
std::vector<FaceGroup> group_by_face(const InterferenceReport& report, const TriangleMesh& ma, const TriangleMesh& mb,
                                     const MeshParts& a, const MeshParts& b);

// How deep each group's faces overlap: the deepest vertex of its intersecting triangles that lies
// inside the other solid, its distance to that solid's surface (0 where only edges cross, as at
// a touch). A lower bound of the overlap there, exact where the deepest point is a vertex (flat
// CAD faces). `b` as placed. Returns the largest over the groups.
double measure_overlap_depths(std::vector<FaceGroup>& groups, const InterferenceReport& report, const TriangleMesh& a,
                              const TriangleMesh& b, const MeshParts& pa, const MeshParts& pb);

// Where a face (patch) of MeshParts is: the area-weighted centroid of its triangles and its area,
// in the mesh's units; what names a face across re-meshings and renumberings (the review
// server's durable keys).
struct FaceShape {
  geometry::Vec3 centroid = geometry::Vec3::Zero();
  double area = 0;
};
std::vector<FaceShape> face_shapes(const TriangleMesh& mesh, const MeshParts& parts);

// Both meshes in one ASCII PLY: A grey, B blue, triangles in contact yellow, interfering ones
// red; the face quality says the same as a number (0 free, 1 contact, 2 interfering).
void write_interference_ply(std::ostream& out, const TriangleMesh& a, const TriangleMesh& b,
                            const InterferenceReport& report);

}  // namespace mtcs::mesh
