#include "thermal/kernels/heat_source_tree.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace mtcs::thermal {

namespace {

constexpr int kLeafSize = 1;

Vec3 centroid(const HeatedTriangle& t) { return (t.a + t.b + t.c) / 3; }
double area(const HeatedTriangle& t) { return 0.5 * (t.b - t.a).cross(t.c - t.a).norm(); }

}  // namespace

HeatSourceTree::HeatSourceTree(std::span<const HeatedTriangle> triangles, double theta) : theta2_(theta * theta) {
  std::vector<HeatedTriangle> heated;
  for (const HeatedTriangle& t : triangles)
    if (t.flux != 0) heated.push_back(t);
  if (heated.empty()) return;
  std::vector<int> order(heated.size());
  std::iota(order.begin(), order.end(), 0);
  nodes_.reserve(2 * heated.size() / kLeafSize + 2);
  build(order, 0, int(heated.size()), heated);
  sources_.reserve(heated.size());
  flux_.reserve(heated.size());
  for (const int i : order) sources_.emplace_back(heated[i].a, heated[i].b, heated[i].c), flux_.push_back(heated[i].flux);
}

// Splits order[first, first + count) at the median centroid along the longest side of the
// centroids' bounds, and sums the moments of a uniform source on each triangle about the
// node's centre: charge f A, dipole f A (g - c), second moment
// f A / 12 (a a^T + b b^T + c c^T + s s^T) with corners relative to c and s their sum.
int HeatSourceTree::build(std::vector<int>& order, int first, int count, std::span<const HeatedTriangle> triangles) {
  const int index = int(nodes_.size());
  nodes_.emplace_back();
  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY), clo = lo, chi = hi;
  for (int k = first; k < first + count; ++k) {
    const HeatedTriangle& t = triangles[order[k]];
    for (const Vec3& v : {t.a, t.b, t.c}) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
    const Vec3 g = centroid(t);
    clo = clo.cwiseMin(g), chi = chi.cwiseMax(g);
  }
  Node node;
  node.centre = 0.5 * (lo + hi);
  node.first = first;
  node.count = count;
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  for (int k = first; k < first + count; ++k) {
    const HeatedTriangle& t = triangles[order[k]];
    const Vec3 a = t.a - node.centre, b = t.b - node.centre, c = t.c - node.centre, s = a + b + c;
    const double q = t.flux * area(t);
    node.charge += q;
    node.dipole += q * s / 3;
    second += (q / 12) * (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
    node.radius = std::max({node.radius, a.norm(), b.norm(), c.norm()});
  }
  node.quadrupole = 3 * second - second.trace() * Eigen::Matrix3d::Identity();
  if (count > kLeafSize) {
    int axis = 0;
    (chi - clo).maxCoeff(&axis);
    const int mid = first + count / 2;
    std::nth_element(order.begin() + first, order.begin() + mid, order.begin() + first + count,
                     [&](int i, int j) { return centroid(triangles[i])[axis] < centroid(triangles[j])[axis]; });
    node.children[0] = build(order, first, mid - first, triangles);
    node.children[1] = build(order, mid, first + count - mid, triangles);
  }
  nodes_[index] = node;
  return index;
}

double HeatSourceTree::potential(const Vec3& p) const {
  if (nodes_.empty()) return 0;
  double sum = 0;
  int stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& n = nodes_[stack[--top]];
    const Vec3 r = p - n.centre;
    const double r2 = r.squaredNorm();
    if (n.radius * n.radius < theta2_ * r2) {  // far: the expansion (phi = q/R + d.r/R^3 + r^T Q r / 2R^5)
      const double inv2 = 1 / r2, inv = std::sqrt(inv2);
      sum += inv * (n.charge + inv2 * (n.dipole.dot(r) + 0.5 * inv2 * r.dot(n.quadrupole * r)));
    } else if (n.children[0] < 0) {
      for (int k = n.first; k < n.first + n.count; ++k) sum += flux_[k] * sources_[k].potential(p);
    } else {
      stack[top++] = n.children[1];
      stack[top++] = n.children[0];
    }
  }
  return sum;
}

}  // namespace mtcs::thermal
