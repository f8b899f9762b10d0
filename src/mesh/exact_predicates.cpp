// The orientation filters of Shewchuk ("Adaptive precision floating-point arithmetic and fast
// robust geometric predicates", 1997, the stage-A bounds of orient2d and orient3d), with CGAL's
// exact kernel behind them for the undecided cases.

#include "mtcs/mesh/exact_predicates.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>

namespace mtcs::mesh {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
constexpr double kEps = 0x1p-53;  // half an ulp of 1
constexpr double kOrient3dBound = (7 + 56 * kEps) * kEps;
constexpr double kOrient2dBound = (3 + 16 * kEps) * kEps;
// Below this the products may have underflowed and the bound no longer holds.
constexpr double kTiny = 1e-200;

int sign(double v) { return (v > 0) - (v < 0); }

}  // namespace

int orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  // Shewchuk's orient3d(a, b, c, d) is positive when d lies below the counter-clockwise
  // (a, b, c): the negation of ours.
  const double adx = a.x() - d.x(), bdx = b.x() - d.x(), cdx = c.x() - d.x();
  const double ady = a.y() - d.y(), bdy = b.y() - d.y(), cdy = c.y() - d.y();
  const double adz = a.z() - d.z(), bdz = b.z() - d.z(), cdz = c.z() - d.z();
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double det = adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy) + cdz * (adxbdy - bdxady);
  const double permanent = (std::abs(bdxcdy) + std::abs(cdxbdy)) * std::abs(adz) +
                           (std::abs(cdxady) + std::abs(adxcdy)) * std::abs(bdz) +
                           (std::abs(adxbdy) + std::abs(bdxady)) * std::abs(cdz);
  if (permanent > kTiny && std::abs(det) > kOrient3dBound * permanent) return -sign(det);
  const K::Point_3 pa(a.x(), a.y(), a.z()), pb(b.x(), b.y(), b.z()), pc(c.x(), c.y(), c.z()), pd(d.x(), d.y(), d.z());
  return int(CGAL::orientation(pa, pb, pc, pd));
}

int orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
  const double left = (ax - cx) * (by - cy), right = (ay - cy) * (bx - cx);
  const double det = left - right;
  const double detsum = std::abs(left) + std::abs(right);
  if (detsum > kTiny && std::abs(det) > kOrient2dBound * detsum) return sign(det);
  return int(CGAL::orientation(K::Point_2(ax, ay), K::Point_2(bx, by), K::Point_2(cx, cy)));
}

}  // namespace mtcs::mesh
