#include "fcl_interference_peer.h"

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/distance.h>

namespace mtcs::cli {

struct FclMesh::Impl {
  fcl::BVHModel<fcl::OBBRSSd> model;
};

FclMesh::FclMesh(const mesh::TriangleMesh& m) : impl_(new Impl) {
  std::vector<fcl::Vector3d> vertices(m.vertices.begin(), m.vertices.end());
  std::vector<fcl::Triangle> triangles;
  triangles.reserve(m.triangles.size());
  for (const auto& t : m.triangles) triangles.emplace_back(std::size_t(t[0]), std::size_t(t[1]), std::size_t(t[2]));
  impl_->model.beginModel(int(triangles.size()), int(vertices.size()));
  impl_->model.addSubModel(vertices, triangles);
  impl_->model.endModel();
}

FclMesh::~FclMesh() = default;
FclMesh::FclMesh(FclMesh&&) noexcept = default;

std::vector<std::array<int, 2>> fcl_colliding_pairs(const FclMesh& a, const FclMesh& b) {
  // All contacts, without contact points: FCL then runs its triangle test only.
  fcl::CollisionRequestd request(std::size_t(1) << 30, false);
  fcl::CollisionResultd result;
  const fcl::Transform3d identity = fcl::Transform3d::Identity();
  fcl::collide(&a.impl_->model, identity, &b.impl_->model, identity, request, result);
  std::vector<std::array<int, 2>> pairs;
  pairs.reserve(result.numContacts());
  for (std::size_t i = 0; i < result.numContacts(); ++i) {
    const auto& c = result.getContact(i);
    pairs.push_back({int(c.b1), int(c.b2)});
  }
  return pairs;
}

double fcl_mesh_distance(const FclMesh& a, const FclMesh& b) {
  fcl::DistanceRequestd request;
  fcl::DistanceResultd result;
  const fcl::Transform3d identity = fcl::Transform3d::Identity();
  return fcl::distance(&a.impl_->model, identity, &b.impl_->model, identity, request, result);
}

}  // namespace mtcs::cli
