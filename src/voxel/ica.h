#pragma once
// Inaccessible cone angles (Chen et al., ICPP 2019, section 3): a sphere of radius rho whose
// centre lies at distance D from the pivot meets the tool (rotationally symmetric about d) for
// a set of angles theta between d and the centre that depends only on D and rho. In the
// meridian half-plane the sphere centre is P = D (cos theta, sin theta) and the tool is the
// union of rectangles [a, b] x [0, r]: the sphere meets cylinder i iff P lies within rho of
// rectangle i.
//
// The paper summarises that set by one angle (ICA). It need not start at theta = 0 (a sphere just
// beyond the tool's end is missed head-on and met at a small angle), so here a node keeps, in
// u = cos theta, an inner interval where its inscribed sphere certainly meets the tool and the
// outer hull of the directions where its circumscribed sphere may meet it; everything else is
// the corner case.

#include <algorithm>
#include <cmath>
#include <vector>

#include "mtcs/geometry/primitives.h"

#include "mtcs/voxel/tool.h"

namespace mtcs::voxel::detail {

// Margin (mm) by which inscribed spheres are shrunk and circumscribed ones grown, so that the
// rounding of the double computations below (~1e-13 mm at part scale) never turns a verdict.
constexpr double kSphereMargin = 1e-9;

enum class SphereVerdict : unsigned char { hit, miss, corner };

// Direct test for one direction: x = axial coordinate of the centre, y2 = its squared distance
// from the axis; hit when the sphere of squared radius in2 meets the tool, miss when the one of
// squared radius out2 does not. The square root of y2 is taken only when the centre lies
// outside a cylinder's radius but within reach of it.
inline SphereVerdict sphere_verdict(const Tool& tool, double x, double y2, double in2, double out2) {
  bool maybe = false;
  double y = -1;
  for (const ToolCylinder& c : tool) {
    const double dx = std::max({c.a - x, x - c.b, 0.0}), dx2 = dx * dx;
    if (dx2 >= out2) continue;
    double d2 = dx2;
    if (y2 > c.r * c.r) {
      if (y < 0) y = std::sqrt(y2);
      const double dy = y - c.r;
      d2 += dy * dy;
    }
    if (d2 <= in2) return SphereVerdict::hit;
    maybe = maybe || d2 < out2;
  }
  return maybe ? SphereVerdict::corner : SphereVerdict::miss;
}

// A corner case (the circumscribed sphere may meet the tool, the inscribed one does not) seen
// through the cube itself rather than its spheres: the cube spans x +- (size/2).|d| along the
// axis and lies at least y - (size/2).|e| from it (e = radial unit vector of the centre), so a
// cylinder it misses on either count cannot touch it; and for a full cube, its corner nearest
// the axis lying inside a cylinder is a collision. Anything else stays a corner case.
inline SphereVerdict refine_corner(const Tool& tool, const Vec3& size, const Vec3& d, const Vec3& radial, double x, double y,
                                   bool full) {
  const double half_axial = 0.5 * (size.x() * std::abs(d.x()) + size.y() * std::abs(d.y()) + size.z() * std::abs(d.z()));
  double half_radial = 0;
  if (y > 0)
    half_radial = 0.5 * (size.x() * std::abs(radial.x()) + size.y() * std::abs(radial.y()) + size.z() * std::abs(radial.z())) / y;
  bool maybe = false;
  for (const ToolCylinder& c : tool)
    maybe = maybe || (x - half_axial <= c.b + kSphereMargin && x + half_axial >= c.a - kSphereMargin &&
                      (y == 0 || y - half_radial <= c.r + kSphereMargin));
  if (!maybe) return SphereVerdict::miss;
  if (full && y > 0) {
    // The corner towards the axis: centre - (size/2) sign(e), in axial / radial coordinates.
    Vec3 q;
    for (int k = 0; k < 3; ++k) q[k] = radial[k] > 0 ? -0.5 * size[k] : 0.5 * size[k];
    const double qx = x + q.dot(d);
    const Vec3 qr = radial + q - q.dot(d) * d;
    const double qy = qr.norm();
    for (const ToolCylinder& c : tool)
      if (qx >= c.a + kSphereMargin && qx <= c.b - kSphereMargin && qy <= c.r - kSphereMargin) return SphereVerdict::hit;
  }
  return SphereVerdict::corner;
}

// Intervals of u = cos theta; empty when lo > hi.
struct ConeInterval {
  double lo = 1;
  double hi = -1;
  bool contains(double u) const { return lo <= u && u <= hi; }
};

struct NodeCone {
  ConeInterval hit;      // inscribed sphere (radius rho_in - margin) meets the tool for every u in it
  ConeInterval reach;    // circumscribed sphere (radius rho_out + margin) misses the tool outside it
};

NodeCone node_cone(const Tool& tool, double distance, double rho_in, double rho_out);

}  // namespace mtcs::voxel::detail
