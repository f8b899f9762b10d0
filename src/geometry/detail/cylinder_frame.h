#pragma once
// A cylinder in a local frame (axis unit w, rim basis u, v) and the closed-form signed distance
// from a point to the solid cylinder, evaluated along a rim of another cylinder.

#include <array>

#include "real.h"

namespace mtcs::geometry::detail {

template <class R>
struct CylFrame {
  V3<R> p0;   // base centre
  V3<R> d;    // axis vector p1 - p0
  V3<R> w;    // unit axis (+z for a zero-length axis)
  V3<R> u, v; // unit vectors completing w
  R len;
  R r;

  V3<R> p1() const { return p0 + d; }
};

template <class R>
CylFrame<R> make_frame(const V3<R>& p0, const V3<R>& d, R r) {
  CylFrame<R> c;
  c.p0 = p0;
  c.d = d;
  c.r = r;
  c.len = norm(d);
  c.w = c.len > R(0) ? d * (R(1) / c.len) : V3<R>{R(0), R(0), R(1)};
  orthonormal_basis(c.w, &c.u, &c.v);
  return c;
}

// Where on the solid the closest point lies.
enum class Region { Shell, Disk, Rim, Inside };

// A circle (centre c, radius rc, basis u, v) seen in the frame of cylinder `b`: the axial
// coordinate t(theta) and the radial vector rad(theta) are affine in (cos, sin), so each
// evaluation costs a few multiply-adds and one square root.
template <class R>
struct CircleInFrame {
  R tc, tu, tv;
  V3<R> r0, ru, rv;

  CircleInFrame(const V3<R>& c, R rc, const V3<R>& u, const V3<R>& v, const CylFrame<R>& b) {
    const V3<R> cq = c - b.p0;
    tc = dot(cq, b.w);
    r0 = cq - tc * b.w;
    const R uw = dot(u, b.w), vw = dot(v, b.w);
    tu = rc * uw;
    tv = rc * vw;
    ru = rc * (u - uw * b.w);
    rv = rc * (v - vw * b.w);
  }

  R axial(R co, R si) const { return tc + tu * co + tv * si; }
  R radial(R co, R si) const { return norm(r0 + co * ru + si * rv); }
};

// Signed distance from a point with axial coordinate t and distance rho from the axis to the
// solid cylinder of length len and radius r: negative inside, by the depth to the boundary.
template <class R>
R solid_signed_distance(R t, R rho, R len, R r) {
  const R radial = rho - r;
  R axial;
  if (t < R(0)) {
    axial = -t;
  } else if (t > len) {
    axial = t - len;
  } else {
    if (radial > R(0)) return radial;
    return -min_(-radial, min_(t, len - t));
  }
  return radial > R(0) ? sqrt_(axial * axial + radial * radial) : axial;
}

// The signed distance from the points of a circle to a solid cylinder (length len, radius rb),
// with its angle derivatives for Newton's method. Piecewise smooth: C1 outside the solid.
template <class R>
struct RimToSolid {
  const CircleInFrame<R>& c;
  R len, rb;

  R operator()(R co, R si) const {
    return solid_signed_distance(c.axial(co, si), c.radial(co, si), len, rb);
  }

  // All samples at once, branch-free, so that the compiler vectorises the loops.
  template <std::size_t N>
  void sample(const std::array<R, N>& co, const std::array<R, N>& si, std::array<R, N>& out) const {
    std::array<R, N> t, rho;
    for (std::size_t k = 0; k < N; ++k) {
      t[k] = c.tc + c.tu * co[k] + c.tv * si[k];
      const R x = c.r0.x + c.ru.x * co[k] + c.rv.x * si[k];
      const R y = c.r0.y + c.ru.y * co[k] + c.rv.y * si[k];
      const R z = c.r0.z + c.ru.z * co[k] + c.rv.z * si[k];
      rho[k] = sqrt_(x * x + y * y + z * z);
    }
    for (std::size_t k = 0; k < N; ++k) {
      // Plain selects (no short-circuit operators) so that the loop stays branch-free.
      R ax = -t[k] > t[k] - len ? -t[k] : t[k] - len;
      ax = ax > R(0) ? ax : R(0);
      const R radial = rho[k] - rb;
      const R rp = radial > R(0) ? radial : R(0);
      const R outside = sqrt_(ax * ax + rp * rp);
      R depth = t[k] < len - t[k] ? t[k] : len - t[k];
      depth = -radial < depth ? -radial : depth;
      const R excess = ax > rp ? ax : rp;  // > 0 exactly when the point is outside
      out[k] = excess > R(0) ? outside : -depth;
    }
  }

  Jet<R> jet(R co, R si) const {
    const R t = c.tc + c.tu * co + c.tv * si;
    const R t1 = -c.tu * si + c.tv * co, t2 = c.tc - t;
    const V3<R> rad = c.r0 + co * c.ru + si * c.rv;
    const V3<R> rad1 = si * -c.ru + co * c.rv, rad2 = rad - c.r0;
    const R rho = norm(rad);
    R rho1 = R(0), rho2 = R(0);
    if (rho > R(0)) {
      rho1 = dot(rad, rad1) / rho;
      rho2 = (norm2(rad1) - dot(rad, rad2) - rho1 * rho1) / rho;
    }
    const R dr = rho - rb;
    if (t >= R(0) && t <= len) {
      if (dr > R(0)) return {dr, rho1, rho2};
      // Inside: minus the depth to the nearest of shell and end planes.
      const R to0 = t, to1 = len - t;
      if (-dr <= to0 && -dr <= to1) return {dr, rho1, rho2};
      if (to0 <= to1) return {-t, -t1, -t2};
      return {t - len, t1, t2};
    }
    const R sign = t < R(0) ? R(-1) : R(1);
    const R ax = t < R(0) ? -t : t - len, ax1 = sign * t1, ax2 = sign * t2;
    if (dr <= R(0)) return {ax, ax1, ax2};
    const R f = sqrt_(ax * ax + dr * dr);
    const R f1 = (ax * ax1 + dr * rho1) / f;
    return {f, f1, (ax1 * ax1 + ax * ax2 + rho1 * rho1 + dr * rho2 - f1 * f1) / f};
  }
};

// Closest point of solid `b` to the point x (x itself when inside), and its region.
template <class R>
V3<R> closest_point_on_solid(const CylFrame<R>& b, const V3<R>& x, Region* region) {
  const V3<R> y = x - b.p0;
  const R t = dot(y, b.w);
  const V3<R> rad = y - t * b.w;
  const R rho = norm(rad);
  const bool out_axial = t < R(0) || t > b.len;
  const bool out_radial = rho > b.r;
  if (!out_axial && !out_radial) {
    *region = Region::Inside;
    return x;
  }
  *region = out_axial ? (out_radial ? Region::Rim : Region::Disk) : Region::Shell;
  const R tcl = t < R(0) ? R(0) : (t > b.len ? b.len : t);
  const V3<R> radcl = out_radial ? rad * (b.r / rho) : rad;
  return b.p0 + tcl * b.w + radcl;
}

}  // namespace mtcs::geometry::detail
