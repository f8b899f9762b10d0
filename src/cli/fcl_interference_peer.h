#pragma once
// FCL 0.7's mesh-vs-mesh collision with all contacts (BVHModel<OBBRSS>), the peer of mtcs
// interfere in benchmarks. Private to the cli module: no FCL type leaks out.

#include <array>
#include <memory>
#include <vector>

#include "mtcs/mesh/triangle_mesh.h"

namespace mtcs::cli {

class FclMesh {
 public:
  explicit FclMesh(const mesh::TriangleMesh& mesh);  // builds the OBBRSS hierarchy
  ~FclMesh();
  FclMesh(FclMesh&&) noexcept;

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

}  // namespace mtcs::cli
