// CheckBox in double with a running error bound, rerun in binary128 near ties
// (check_box.h states the method and the margin).

#include "check_box.h"

#include <quadmath.h>

#include <algorithm>
#include <cmath>

namespace mtcs::voxel {
namespace {

using quad = __float128;

template <class T>
struct Unit;
template <>
struct Unit<double> {
  static constexpr double value = 0x1p-53;
};
template <>
struct Unit<quad> {
  static quad value() { return scalbnq(quad(1), -113); }
};
template <class T>
T unit_roundoff() {
  if constexpr (std::is_same_v<T, double>) return Unit<double>::value;
  else return Unit<quad>::value();
}

template <class T>
T abs_(T x) { return x < T(0) ? -x : x; }
inline double sqrt_(double x) { return std::sqrt(x); }
inline quad sqrt_(quad x) { return sqrtq(x); }

// A value and a bound on its distance to the exact value it stands for.
template <class T>
struct Cert {
  T v = 0;
  T e = 0;

  Cert() = default;
  Cert(T value, T err = 0) : v(value), e(err) {}  // NOLINT: exact inputs convert implicitly

  static Cert rounded(T value, T propagated) {
    const T u = unit_roundoff<T>();
    return {value, propagated * (1 + 4 * u) + u * abs_(value)};
  }
  friend Cert operator+(const Cert& a, const Cert& b) { return rounded(a.v + b.v, a.e + b.e); }
  friend Cert operator-(const Cert& a, const Cert& b) { return rounded(a.v - b.v, a.e + b.e); }
  friend Cert operator*(const Cert& a, const Cert& b) {
    return rounded(a.v * b.v, abs_(a.v) * b.e + abs_(b.v) * a.e + a.e * b.e);
  }
  // Requires |b.v| > b.e.
  friend Cert operator/(const Cert& a, const Cert& b) {
    const T den = abs_(b.v) * (abs_(b.v) - b.e);
    return rounded(a.v / b.v, (a.e * abs_(b.v) + abs_(a.v) * b.e) / den);
  }
  Cert operator-() const { return {-v, e}; }
};

template <class T>
Cert<T> max_(const Cert<T>& a, const Cert<T>& b) { return {std::max(a.v, b.v), std::max(a.e, b.e)}; }
template <class T>
Cert<T> min_(const Cert<T>& a, const Cert<T>& b) { return {std::min(a.v, b.v), std::max(a.e, b.e)}; }
// 1-Lipschitz in each argument when lo <= hi.
template <class T>
Cert<T> clamp_(const Cert<T>& x, const Cert<T>& lo, const Cert<T>& hi) {
  return {std::clamp(x.v, lo.v, std::max(lo.v, hi.v)), std::max({x.e, lo.e, hi.e})};
}
template <class T>
Cert<T> sqrt_c(const Cert<T>& x) {
  const T v = std::max(x.v, T(0)), s = sqrt_(v);
  const T e = v > x.e ? x.e / (sqrt_(v - x.e) + s) : sqrt_(v + x.e);
  return Cert<T>::rounded(s, e);
}

enum class Tri : std::uint8_t { no, yes, unsure };

template <class T>
Tri le(const Cert<T>& x, const Cert<T>& y) {
  const Cert<T> d = x - y;
  if (d.v + d.e <= 0) return Tri::yes;
  if (d.v - d.e > 0) return Tri::no;
  return Tri::unsure;
}
Tri all(Tri a, Tri b) {
  if (a == Tri::no || b == Tri::no) return Tri::no;
  return a == Tri::yes && b == Tri::yes ? Tri::yes : Tri::unsure;
}
Tri any(Tri a, Tri b) {
  if (a == Tri::yes || b == Tri::yes) return Tri::yes;
  return a == Tri::no && b == Tri::no ? Tri::no : Tri::unsure;
}

// The unit direction, 1 - d_k^2 and sqrt(1 - d_k^2), with error bounds. A direction along an
// axis is exact.
template <class T>
struct Frame {
  Cert<T> d[3], a[3], ext[3];
};

template <class T>
Frame<T> make_frame(const Vec3& dir) {
  Frame<T> f;
  const int zeros = (dir.x() == 0) + (dir.y() == 0) + (dir.z() == 0);
  if (zeros == 2) {
    for (int k = 0; k < 3; ++k) f.d[k] = Cert<T>(dir[k] > 0 ? T(1) : (dir[k] < 0 ? T(-1) : T(0)));
  } else {
    const Cert<T> x(T(dir.x())), y(T(dir.y())), z(T(dir.z()));
    const Cert<T> n = sqrt_c(x * x + y * y + z * z);
    for (int k = 0; k < 3; ++k) f.d[k] = dir[k] == 0 ? Cert<T>(0) : Cert<T>(T(dir[k])) / n;
  }
  for (int k = 0; k < 3; ++k) {
    if (zeros == 2) {
      f.a[k] = f.ext[k] = Cert<T>(dir[k] == 0 ? T(1) : T(0));  // exact: 0 or 1
      continue;
    }
    f.a[k] = Cert<T>(1) - f.d[k] * f.d[k];
    f.ext[k] = sqrt_c(f.a[k]);
  }
  return f;
}

template <class T>
Tri cylinder_meets_box(const Frame<T>& f, const Vec3& p, const ToolCylinder& cyl, const Box& box) {
  using C = Cert<T>;
  const C* d = f.d;
  C lo[3], hi[3];
  for (int k = 0; k < 3; ++k) {
    lo[k] = C(T(box.min[k])) - C(T(p[k]));
    hi[k] = C(T(box.max[k])) - C(T(p[k]));
  }
  const C a(T(cyl.a)), b(T(cyl.b)), r(T(cyl.r)), r2 = r * r;
  // Bounding box of the cylinder: certainly apart on one axis -> no contact.
  for (int k = 0; k < 3; ++k) {
    const C ad = a * d[k], bd = b * d[k], ext = r * f.ext[k];
    if (le(min_(ad, bd) - ext, hi[k]) == Tri::no || le(lo[k], max_(ad, bd) + ext) == Tri::no) return Tri::no;
  }
  Tri verdict = Tri::no;
  // (A) the axis segment t d, a <= t <= b, meets the box.
  {
    C tlo = a, thi = b;
    Tri inside = Tri::yes;
    for (int k = 0; k < 3 && inside != Tri::no; ++k) {
      if (d[k].v == 0 && d[k].e == 0) {
        inside = all(inside, all(le(lo[k], C(0)), le(C(0), hi[k])));
        continue;
      }
      C t1 = lo[k] / d[k], t2 = hi[k] / d[k];
      if (d[k].v < 0) std::swap(t1, t2);
      tlo = max_(tlo, t1);
      thi = min_(thi, t2);
    }
    verdict = any(verdict, all(inside, le(tlo, thi)));
    if (verdict == Tri::yes) return verdict;
  }
  // (B) a box edge along axis k, clipped to the slab a <= y.d <= b, within r of the axis line.
  for (int k = 0; k < 3; ++k) {
    const int u = (k + 1) % 3, w = (k + 2) % 3;
    const bool exact_zero = d[k].v == 0 && d[k].e == 0;
    for (int eu = 0; eu < 2; ++eu)
      for (int ew = 0; ew < 2; ++ew) {
        const C U = eu ? hi[u] : lo[u], W = ew ? hi[w] : lo[w];
        const C g = U * d[u] + W * d[w];
        C s0 = lo[k], s1 = hi[k];
        Tri in_slab;
        if (exact_zero) {
          in_slab = all(le(a, g), le(g, b));
        } else {
          C sa = (a - g) / d[k], sb = (b - g) / d[k];
          if (d[k].v < 0) std::swap(sa, sb);
          s0 = max_(s0, sa);
          s1 = min_(s1, sb);
          in_slab = le(s0, s1);
        }
        if (in_slab == Tri::no) continue;
        const C& A = f.a[k];
        C s = s0;  // A == 0: the edge is parallel to the axis and every s gives the same distance
        if (A.v > A.e) s = clamp_(d[k] * g / A, s0, s1);
        else if (A.v != 0 || A.e != 0) in_slab = all(in_slab, Tri::unsure);
        const C along = g + s * d[k];
        const C q = U * U + W * W + s * s - along * along;
        verdict = any(verdict, all(in_slab, le(q, r2)));
        if (verdict == Tri::yes) return verdict;
      }
  }
  // (C) an end disk meets a face inside the face: the point of the face's line in the end plane
  // nearest the disk centre c = t d lies in the face and within r of c.
  for (int end = 0; end < (cyl.a == cyl.b ? 1 : 2); ++end) {
    const C& t = end == 0 ? a : b;
    const C c[3] = {t * d[0], t * d[1], t * d[2]};
    for (int k = 0; k < 3; ++k) {
      const C& A = f.a[k];
      if (A.v == 0 && A.e == 0) continue;  // end plane parallel to the face: edges cover it
      const int u = (k + 1) % 3, w = (k + 2) % 3;
      for (int side = 0; side < 2; ++side) {
        const C delta = (side ? hi[k] : lo[k]) - c[k];
        Tri hit = A.v > A.e ? le(delta * delta, r2 * A) : Tri::unsure;
        if (hit == Tri::no) continue;
        // Foot f = c + (delta / A)(e_k - d_k d), compared after multiplying by A > 0.
        const C fu = A * c[u] - delta * d[k] * d[u], fw = A * c[w] - delta * d[k] * d[w];
        hit = all(hit, all(all(le(A * lo[u], fu), le(fu, A * hi[u])), all(le(A * lo[w], fw), le(fw, A * hi[w]))));
        verdict = any(verdict, hit);
        if (verdict == Tri::yes) return verdict;
      }
    }
  }
  return verdict;
}

template <class T>
Tri tool_meets_box(const Frame<T>& f, const Vec3& p, const Tool& tool, const Box& box) {
  Tri verdict = Tri::no;
  for (const ToolCylinder& c : tool) {
    verdict = any(verdict, cylinder_meets_box(f, p, c, box));
    if (verdict == Tri::yes) break;
  }
  return verdict;
}

}  // namespace

CheckBox::CheckBox(const Vec3& pivot, const Vec3& direction, const Tool& tool)
    : pivot_(pivot), direction_(direction), tool_(&tool) {
  const Frame<double> f = make_frame<double>(direction);
  for (int k = 0; k < 3; ++k) {
    d_[k] = f.d[k].v, d_err_[k] = f.d[k].e;
    a_[k] = f.a[k].v, a_err_[k] = f.a[k].e;
    ext_[k] = f.ext[k].v, ext_err_[k] = f.ext[k].e;
  }
}

BoxVerdict CheckBox::operator()(const Box& box) const {
  Frame<double> f;
  for (int k = 0; k < 3; ++k) {
    f.d[k] = {d_[k], d_err_[k]};
    f.a[k] = {a_[k], a_err_[k]};
    f.ext[k] = {ext_[k], ext_err_[k]};
  }
  const Tri fast = tool_meets_box(f, pivot_, *tool_, box);
  if (fast != Tri::unsure) return {fast == Tri::yes, Precision::double_precision};
  const Tri slow = tool_meets_box(make_frame<quad>(direction_), pivot_, *tool_, box);
  if (slow != Tri::unsure) return {slow == Tri::yes, Precision::quad_precision};
  return {true, Precision::undecided};
}

}  // namespace mtcs::voxel
