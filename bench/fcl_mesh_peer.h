#pragma once
// FCL 0.7 on triangle meshes (a BVHModel<OBBRSS> over the triangles), the peer of our mesh
// queries in benchmarks and a second opinion in tests: solid cylinder vs mesh distance, all
// colliding triangle pairs of two meshes, mesh-vs-mesh distance. FCL sees surfaces only: a
// cylinder buried inside the solid gets a positive distance. No FCL type leaks out.

#include <array>
#include <memory>
#include <vector>

#include "mtcs/geometry/primitives.h"
#include "mtcs/mesh/triangle_mesh.h"

namespace mtcs::bench {

class FclMesh {
 public:
  explicit FclMesh(const mesh::TriangleMesh& mesh);  // builds the OBBRSS hierarchy
  ~FclMesh();
  FclMesh(FclMesh&&) noexcept;
  // FCL's distance from the solid cylinder to the surface; 0 when FCL reports a collision.
  double distance(const geometry::Cylinder& cylinder) const;

  // Every colliding triangle pair (FCL's triangle test, floating point), as FCL reports them.
  friend std::vector<std::array<int, 2>> fcl_colliding_pairs(const FclMesh& a, const FclMesh& b);
  friend double fcl_mesh_distance(const FclMesh& a, const FclMesh& b);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

std::vector<std::array<int, 2>> fcl_colliding_pairs(const FclMesh& a, const FclMesh& b);

// FCL's distance between the two surfaces (its exact mode: no relative error allowed).
double fcl_mesh_distance(const FclMesh& a, const FclMesh& b);

}  // namespace mtcs::bench
