// Circle-line, circle-circle and circle-disk distances by minimisation over the circle's angle
// (method in circle_distance.h).

#include "circle_distance.h"

#include "detail/circle_minimize.h"
#include "detail/cylinder_frame.h"

namespace mtcs::geometry {
namespace {

using V = detail::V3<double>;
using detail::from_eigen;

// The other element's frame: a zero-radius "cylinder" whose axis is the line or the normal.
detail::CylFrame<double> frame_of(const Vec3& origin, const Vec3& direction, double radius) {
  return detail::make_frame<double>(from_eigen<double>(origin), from_eigen<double>(direction), radius);
}

template <class F>
CircleClosest run(const Circle& c, const detail::CylFrame<double>& other, double scale,
                  const CircleQuery& q, F&& metric, Vec3 (*closest)(const detail::CylFrame<double>&, const V&)) {
  V u, v;
  const V n = from_eigen<double>(c.normal.normalized());
  detail::orthonormal_basis(n, &u, &v);
  const detail::CircleInFrame<double> in(from_eigen<double>(c.center), c.radius, u, v, other);
  auto f = [&](double co, double si) { return metric(in.axial(co, si), in.radial(co, si)); };
  const double inf = std::numeric_limits<double>::infinity();
  const auto m = detail::minimize_on_circle<double>(f, c.radius, inf, -inf, q.tolerance * std::max(1.0, scale),
                                                    /*between_samples=*/true);
  const V x = from_eigen<double>(c.center) + c.radius * (m.cos_t * u + m.sin_t * v);
  return {m.value, detail::to_eigen(x), closest(other, x)};
}

}  // namespace

CircleClosest circle_line_distance(const Circle& c, const Vec3& origin, const Vec3& direction,
                                   const CircleQuery& q) {
  const auto line = frame_of(origin, direction.normalized(), 0.0);
  const double scale = std::max(c.radius, (c.center - origin).norm());
  return run(c, line, scale, q, [](double, double rho) { return rho; },
             [](const detail::CylFrame<double>& l, const V& x) {
               return detail::to_eigen(l.p0 + detail::dot(x - l.p0, l.w) * l.w);
             });
}

CircleClosest circle_circle_distance(const Circle& a, const Circle& b, const CircleQuery& q) {
  const auto fb = frame_of(b.center, b.normal.normalized(), b.radius);
  const double scale = std::max({a.radius, b.radius, (a.center - b.center).norm()});
  const double rb = b.radius;
  return run(a, fb, scale, q,
             [rb](double t, double rho) { return std::hypot(t, rho - rb); },
             [](const detail::CylFrame<double>& f, const V& x) {
               const V y = x - f.p0;
               V rad = y - detail::dot(y, f.w) * f.w;
               const double rho = detail::norm(rad);
               rad = rho > 0 ? rad * (f.r / rho) : f.u * f.r;  // centre-on-axis: any rim point
               return detail::to_eigen(f.p0 + rad);
             });
}

CircleClosest circle_disk_distance(const Circle& c, const Circle& disk, const CircleQuery& q) {
  const auto fd = frame_of(disk.center, disk.normal.normalized(), disk.radius);
  const double scale = std::max({c.radius, disk.radius, (c.center - disk.center).norm()});
  const double rd = disk.radius;
  return run(c, fd, scale, q,
             [rd](double t, double rho) { return std::hypot(t, std::max(0.0, rho - rd)); },
             [](const detail::CylFrame<double>& f, const V& x) {
               const V y = x - f.p0;
               V rad = y - detail::dot(y, f.w) * f.w;
               const double rho = detail::norm(rad);
               if (rho > f.r) rad = rad * (f.r / rho);
               return detail::to_eigen(f.p0 + rad);
             });
}

}  // namespace mtcs::geometry
