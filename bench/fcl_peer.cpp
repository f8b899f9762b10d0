#include "fcl_peer.h"

#include <fcl/narrowphase/distance.h>

#include <algorithm>

namespace mtcs::bench {
namespace {

// FCL cylinders are centred at the origin with the axis along z.
fcl::Transform3d pose_of(const geometry::Cylinder& c) {
  const Eigen::Vector3d axis = c.p1 - c.p0;
  fcl::Transform3d tf = fcl::Transform3d::Identity();
  tf.translation() = (c.p0 + c.p1) / 2;
  if (axis.norm() > 0) {
    tf.linear() = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), axis).toRotationMatrix();
  }
  return tf;
}

}  // namespace

struct FclPair::Impl {
  fcl::Cylinderd a, b;
  fcl::Transform3d ta, tb;
};

FclPair::FclPair(const geometry::Cylinder& a, const geometry::Cylinder& b)
    : impl_(new Impl{fcl::Cylinderd(a.radius, (a.p1 - a.p0).norm()),
                     fcl::Cylinderd(b.radius, (b.p1 - b.p0).norm()), pose_of(a), pose_of(b)}) {}

FclPair::~FclPair() = default;
FclPair::FclPair(FclPair&&) noexcept = default;

double FclPair::distance() const {
  fcl::DistanceRequestd request;
  fcl::DistanceResultd result;
  const double d = fcl::distance(&impl_->a, impl_->ta, &impl_->b, impl_->tb, request, result);
  return std::max(0.0, d);
}

}  // namespace mtcs::bench
