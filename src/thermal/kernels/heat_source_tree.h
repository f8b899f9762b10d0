#pragma once
// The heat input's potential, sum_i flux_i * integral over T_i of dA / |p - y|, over many heated
// triangles (a mesh cavity has thousands) at many points: a tree of triangle groups in which a
// group far from p (its bounding sphere's radius below theta times the distance to its centre)
// takes its multipole expansion to the quadrupole, and the triangles of the groups near p their
// closed form (TriangleSource). Barnes-Hut: the cost per point grows with log N, not N.
// Truncation: the first term left out is the octupole, relative to a far group's own field
// at most ~theta^3; measured against the exact sum in tests/thermal/heat_source_tree_test.cpp.

#include <span>
#include <vector>

#include <Eigen/Dense>

#include "mtcs/thermal/model.h"
#include "thermal/kernels/segment_potential.h"

namespace mtcs::thermal {

class HeatSourceTree {
 public:
  // triangles with flux 0 are left out (they add nothing).
  HeatSourceTree(std::span<const HeatedTriangle> triangles, double theta);
  double potential(const Vec3& p) const;
  std::size_t size() const { return sources_.size(); }

 private:
  struct Node {
    Vec3 centre = Vec3::Zero();
    double radius = 0;  // every corner of its triangles lies within this of centre
    double charge = 0;  // sum flux * area
    Vec3 dipole = Vec3::Zero();                            // about centre
    Eigen::Matrix3d quadrupole = Eigen::Matrix3d::Zero();  // traceless, about centre
    int first = 0, count = 0;  // its triangles: sources_[first, first + count)
    int children[2] = {-1, -1};
  };
  int build(std::vector<int>& order, int first, int count, std::span<const HeatedTriangle> triangles);
  double theta2_ = 0;
  std::vector<TriangleSource> sources_;
  std::vector<double> flux_;
  std::vector<Node> nodes_;
};

}  // namespace mtcs::thermal
