// The cone intervals of a sphere: the circle of radius D about the pivot crosses the boundary of
// "within rho of rectangle i" only where it meets the lines x = a - rho, x = b + rho,
// y = r + rho or the circles of radius rho about the corners (a, r), (b, r); between consecutive
// crossings membership is constant and is read at the midpoint.

#include <algorithm>
#include <cmath>

#include "ica.h"

namespace mtcs::voxel::detail {
namespace {

bool member(const Tool& tool, double D, double u, double rho2) {
  const double x = D * u, y = D * std::sqrt(std::max(0.0, (1 - u) * (1 + u)));
  for (const ToolCylinder& c : tool) {
    const double dx = std::max({c.a - x, x - c.b, 0.0}), dy = std::max(y - c.r, 0.0);
    if (dx * dx + dy * dy <= rho2) return true;
  }
  return false;
}

// Breakpoints in u of the circle of radius D against the rounded rectangles of radius rho.
std::vector<double> breakpoints(const Tool& tool, double D, double rho) {
  std::vector<double> u{-1.0, 1.0};
  const auto add = [&](double v) {
    if (v > -1 && v < 1) u.push_back(v);
  };
  for (const ToolCylinder& c : tool) {
    add((c.a - rho) / D);
    add((c.b + rho) / D);
    const double h = c.r + rho;
    if (D >= h) {
      const double s = std::sqrt((D - h) * (D + h)) / D;
      add(s);
      add(-s);
    }
    for (double corner : {c.a, c.b}) {
      const double q = std::hypot(corner, c.r);
      if (q == 0) continue;
      // Angle psi of the corner; cos(theta - psi) = k where the two circles meet.
      const double k = (D * D + q * q - rho * rho) / (2 * D * q);
      if (k < -1 || k > 1) continue;
      const double psi = std::atan2(c.r, corner), t = std::acos(k);
      add(std::cos(psi + t));
      add(std::cos(psi - t));
    }
  }
  std::sort(u.begin(), u.end());
  u.erase(std::unique(u.begin(), u.end()), u.end());
  return u;
}

// Marked segments [u_i, u_(i+1)] whose midpoint is a member.
std::vector<char> marked(const Tool& tool, double D, double rho, const std::vector<double>& u) {
  std::vector<char> m(u.size() - 1);
  for (std::size_t i = 0; i + 1 < u.size(); ++i) m[i] = member(tool, D, 0.5 * (u[i] + u[i + 1]), rho * rho);
  return m;
}

}  // namespace

NodeCone node_cone(const Tool& tool, double D, double rho_in, double rho_out) {
  constexpr double kSlack = 1e-12;  // in u: covers the rounding of u = w.d / D
  NodeCone cone;
  // Inner: the longest run of marked segments for the shrunk inscribed sphere.
  const double in = rho_in - kSphereMargin;
  if (in > 0) {
    const std::vector<double> u = breakpoints(tool, D, in);
    const std::vector<char> m = marked(tool, D, in, u);
    for (std::size_t i = 0; i < m.size();) {
      if (!m[i]) { ++i; continue; }
      std::size_t j = i;
      while (j < m.size() && m[j]) ++j;
      if (u[j] - u[i] > cone.hit.hi - cone.hit.lo) cone.hit = {u[i], u[j]};
      i = j;
    }
    if (cone.hit.lo <= cone.hit.hi) cone.hit = {cone.hit.lo + kSlack, cone.hit.hi - kSlack};
  }
  // Outer: the hull of the marked segments (and of the end points) for the grown sphere.
  const double out = rho_out + kSphereMargin;
  const std::vector<double> u = breakpoints(tool, D, out);
  const std::vector<char> m = marked(tool, D, out, u);
  for (std::size_t i = 0; i < m.size(); ++i)
    if (m[i]) cone.reach = {std::min(cone.reach.lo, u[i]), std::max(cone.reach.hi, u[i + 1])};
  for (double end : {-1.0, 1.0})
    if (member(tool, D, end, out * out)) cone.reach = {std::min(cone.reach.lo, end), std::max(cone.reach.hi, end)};
  if (cone.reach.lo <= cone.reach.hi) cone.reach = {cone.reach.lo - kSlack, cone.reach.hi + kSlack};
  return cone;
}

}  // namespace mtcs::voxel::detail
