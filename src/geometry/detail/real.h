#pragma once
// Scalar-generic helpers so that every kernel runs in double and, for the verdict of
// near-contact pairs, in 113-bit __float128. A three-component vector of our own keeps the
// kernels free of Eigen's expression templates in the hot path and works for both scalars.

#include <quadmath.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "mtcs/geometry/primitives.h"

namespace mtcs::geometry::detail {

using quad = __float128;

inline double sqrt_(double x) { return std::sqrt(x); }
inline quad sqrt_(quad x) { return sqrtq(x); }
inline double abs_(double x) { return std::fabs(x); }
inline quad abs_(quad x) { return fabsq(x); }
inline void sincos_(double x, double* s, double* c) { ::sincos(x, s, c); }
inline void sincos_(quad x, quad* s, quad* c) { sincosq(x, s, c); }
// std::numeric_limits is not specialised for __float128 in libstdc++ 12.
template <class R>
struct Limits {
  static R infinity() { return std::numeric_limits<R>::infinity(); }
  static R max() { return std::numeric_limits<R>::max(); }
  static R epsilon() { return std::numeric_limits<R>::epsilon(); }
};
template <>
struct Limits<quad> {
  static quad infinity() { return quad(std::numeric_limits<double>::infinity()); }  // clang has no __builtin_huge_valq
  // FLT128_MAX and FLT128_EPSILON, spelled without the Q suffix that -Wpedantic rejects.
  static quad max() { return scalbnq(quad(1.0) - scalbnq(quad(1.0), -113), 16384); }
  static quad epsilon() { return scalbnq(quad(1.0), -112); }
};

template <class R>
R min_(R a, R b) { return b < a ? b : a; }
template <class R>
R max_(R a, R b) { return a < b ? b : a; }
template <class R>
R clamp01(R x) { return x < R(0) ? R(0) : (x > R(1) ? R(1) : x); }

// Value and first two derivatives of a function of one variable.
template <class R>
struct Jet {
  R f, d1, d2;
};

template <class R>
struct V3 {
  R x, y, z;

  V3 operator+(const V3& o) const { return {x + o.x, y + o.y, z + o.z}; }
  V3 operator-(const V3& o) const { return {x - o.x, y - o.y, z - o.z}; }
  V3 operator-() const { return {-x, -y, -z}; }
  V3 operator*(R k) const { return {x * k, y * k, z * k}; }
  friend V3 operator*(R k, const V3& v) { return v * k; }
};

template <class R>
R dot(const V3<R>& a, const V3<R>& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
template <class R>
V3<R> cross(const V3<R>& a, const V3<R>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <class R>
R norm2(const V3<R>& a) { return dot(a, a); }
template <class R>
R norm(const V3<R>& a) { return sqrt_(dot(a, a)); }

template <class R>
V3<R> from_eigen(const Vec3& v) { return {R(v.x()), R(v.y()), R(v.z())}; }
template <class R>
Vec3 to_eigen(const V3<R>& v) { return {double(v.x), double(v.y), double(v.z)}; }

// Orthonormal u, v completing unit n (Duff et al., "Building an Orthonormal Basis, Revisited",
// JCGT 2017): branch-free except for the sign, no singularity.
template <class R>
void orthonormal_basis(const V3<R>& n, V3<R>* u, V3<R>* v) {
  const R sign = n.z < R(0) ? R(-1) : R(1);
  const R a = R(-1) / (sign + n.z);
  const R b = n.x * n.y * a;
  *u = {R(1) + sign * n.x * n.x * a, sign * b, -sign * n.x};
  *v = {b, sign + n.y * n.y * a, -n.y};
}

}  // namespace mtcs::geometry::detail
