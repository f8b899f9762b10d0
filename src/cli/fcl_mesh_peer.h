#pragma once
// FCL 0.7's solid-cylinder vs triangle-mesh distance (a BVHModel<OBBRSS> over the triangles,
// GJK per triangle): the peer in `mtcs bench clearance` and a second opinion in tests. FCL sees
// the surface only: a cylinder buried inside the solid gets a positive distance.

#include <memory>

#include "mtcs/geometry/primitives.h"
#include "mtcs/mesh/triangle_mesh.h"

namespace mtcs::cli {

class FclMesh {
 public:
  explicit FclMesh(const mesh::TriangleMesh& mesh);
  ~FclMesh();
  FclMesh(FclMesh&&) noexcept;
  // FCL's distance from the solid cylinder to the surface; 0 when FCL reports a collision.
  double distance(const geometry::Cylinder& cylinder) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace mtcs::cli
