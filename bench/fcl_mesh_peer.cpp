#include "fcl_mesh_peer.h"

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/distance.h>

#include <algorithm>

namespace mtcs::bench {

struct FclMesh::Impl {
  fcl::BVHModel<fcl::OBBRSSd> model;
};

FclMesh::FclMesh(const mesh::TriangleMesh& mesh) : impl_(new Impl) {
  std::vector<fcl::Vector3d> points(mesh.vertices.begin(), mesh.vertices.end());
  std::vector<fcl::Triangle> triangles;
  triangles.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) triangles.emplace_back(t[0], t[1], t[2]);
  impl_->model.beginModel(int(triangles.size()), int(points.size()));
  impl_->model.addSubModel(points, triangles);
  impl_->model.endModel();
}

FclMesh::~FclMesh() = default;
FclMesh::FclMesh(FclMesh&&) noexcept = default;

double FclMesh::distance(const geometry::Cylinder& c) const {
  // FCL cylinders are centred at the origin with the axis along z.
  const Eigen::Vector3d axis = c.p1 - c.p0;
  fcl::Transform3d pose = fcl::Transform3d::Identity();
  pose.translation() = (c.p0 + c.p1) / 2;
  if (axis.norm() > 0) pose.linear() = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), axis).toRotationMatrix();
  const fcl::Cylinderd cylinder(c.radius, axis.norm());
  fcl::DistanceRequestd request;
  fcl::DistanceResultd result;
  const double d = fcl::distance(&cylinder, pose, &impl_->model, fcl::Transform3d::Identity(), request, result);
  return std::max(0.0, d);
}

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

}  // namespace mtcs::bench
