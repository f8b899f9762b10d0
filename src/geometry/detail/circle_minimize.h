#pragma once
// Global minimum of a function of the angle on a circle, f(cos t, sin t).
//
// The functions minimised here are distances from a point moving on a circle of radius r to a
// convex element: 1-Lipschitz in the point, hence r-Lipschitz in the angle, piecewise smooth,
// with at most a handful of basins. Kernels:
//   1. sample N equally spaced angles (cos/sin from a table: no trigonometry);
//   2. every discrete local minimum whose sample can still beat `best` (sample - r h >= best
//      proves it cannot, by the Lipschitz bound) is refined by Brent's method on its two
//      neighbouring intervals;
//   3. refinement stops when the bracket is narrower than tol / r, i.e. the value is within
//      `tol` of the basin's minimum (Lipschitz again), or at the iteration cap.
// The result never under-estimates: every value returned is f at a real angle.

#include <array>

#include "real.h"

namespace mtcs::geometry::detail {

inline constexpr int kCircleSamples = 24;

template <class R>
struct CircleMin {
  R value;
  R cos_t, sin_t;
};

template <class R>
struct SampleTable {
  std::array<R, kCircleSamples> cos, sin;
};

template <class R>
const SampleTable<R>& circle_sample_table() {
  static const auto table = [] {
    SampleTable<R> t{};
    const R two_pi = R(2) * R(3.14159265358979323846264338327950288L);
    for (int k = 0; k < kCircleSamples; ++k) sincos_(two_pi * R(k) / R(kCircleSamples), &t.sin[k], &t.cos[k]);
    return t;
  }();
  return table;
}

// Brent's minimisation (Numerical Recipes 10.2) of f on [a, b] starting from x with f(x) = fx.
template <class R, class F>
CircleMin<R> brent_on_angle(F& f, R a, R b, R x, R fx, R xtol, int max_iter) {
  const R cgold = R(0.3819660112501051);
  R w = x, v = x, fw = fx, fv = fx, d = R(0), e = R(0);
  for (int iter = 0; iter < max_iter; ++iter) {
    const R xm = (a + b) / R(2);
    const R tol1 = xtol, tol2 = R(2) * tol1;
    if (abs_(x - xm) <= tol2 - (b - a) / R(2)) break;
    if (abs_(e) > tol1) {
      R r = (x - w) * (fx - fv), q = (x - v) * (fx - fw), p = (x - v) * q - (x - w) * r;
      q = R(2) * (q - r);
      if (q > R(0)) p = -p;
      q = abs_(q);
      const R etemp = e;
      e = d;
      if (abs_(p) >= abs_(q * etemp / R(2)) || p <= q * (a - x) || p >= q * (b - x)) {
        e = (x >= xm) ? a - x : b - x;
        d = cgold * e;
      } else {
        d = p / q;
        const R u = x + d;
        if (u - a < tol2 || b - u < tol2) d = (xm >= x) ? tol1 : -tol1;
      }
    } else {
      e = (x >= xm) ? a - x : b - x;
      d = cgold * e;
    }
    const R u = abs_(d) >= tol1 ? x + d : x + (d >= R(0) ? tol1 : -tol1);
    R su, cu;
    sincos_(u, &su, &cu);
    const R fu = f(cu, su);
    if (fu <= fx) {
      if (u >= x) a = x; else b = x;
      v = w, fv = fw, w = x, fw = fx, x = u, fx = fu;
    } else {
      if (u < x) a = u; else b = u;
      if (fu <= fw || w == x) {
        v = w, fv = fw, w = u, fw = fu;
      } else if (fu <= fv || v == x || v == w) {
        v = u, fv = fu;
      }
    }
  }
  R s, c;
  sincos_(x, &s, &c);
  return {fx, c, s};
}

// Safeguarded Newton's method on [a, b] from x, for functions that provide their angle
// derivatives (f.jet), given their jets ja, jb at the bracket ends. Each step is, in order of
// preference: Newton's step, when the model is convex and stays inside the bracket; the
// intersection of the tangents at the bracket ends, which lands on a V-shaped kink (a rim
// grazing the other's rim) in one step; bisection on the sign of f', also forced when three
// steps have not halved the bracket. Stops when the predicted decrease f'^2 / 2f'' is below
// `tol`, or the bracket is narrower than `xtol`. Returns the lowest value evaluated.
template <class R, class F, class EndJets>
CircleMin<R> newton_on_angle(const F& f, R a, R b, R x, EndJets&& end_jets, R tol, R xtol,
                             int max_iter) {
  CircleMin<R> best{Limits<R>::infinity(), R(1), R(0)};
  Jet<R> ja{}, jb{};
  bool tangent_a = false, tangent_b = false, ends_known = false;
  R mark = b - a;
  int slow = 0;
  for (int iter = 0; iter < max_iter; ++iter) {
    R si, co;
    sincos_(x, &si, &co);
    const Jet<R> j = f.jet(co, si);
    if (j.f < best.value) best = {j.f, co, si};
    // A stationary point ends the search only as a minimum: a sample can land exactly on the
    // crest between two minima closer together than the sample spacing (a rim crossing under
    // an edge by a sliver, by an axis-parallel pair's symmetry). From a crest, go right.
    if (j.d1 == R(0) && j.d2 >= R(0)) break;
    const R step = -j.d1 / j.d2;
    if (j.d2 > R(0) && abs_(j.d1 * step) <= tol) {
      // Converged: one last step, kept only if it lowers the value.
      sincos_(x + step, &si, &co);
      const R last = f(co, si);
      if (last < best.value) best = {last, co, si};
      break;
    }
    if (j.d1 > R(0)) b = x, jb = j, tangent_b = true;
    else a = x, ja = j, tangent_a = true;
    if (b - a <= xtol) break;
    if (b - a <= mark / R(2)) mark = b - a, slow = 0;
    else ++slow;

    R next = x + step;
    bool inside = j.d2 > R(0) && next > a && next < b;
    if (!inside && !ends_known) {
      // Newton failed: the bracket ends' jets are worth their cost now. (An end already
      // replaced by an evaluated point keeps that point's jet.)
      ends_known = true;
      Jet<R> ea, eb;
      end_jets(&ea, &eb);
      if (!tangent_a) ja = ea, tangent_a = ea.d1 < R(0);
      if (!tangent_b) jb = eb, tangent_b = eb.d1 > R(0);
    }
    if (!inside && tangent_a && tangent_b) {
      next = (jb.f - ja.f + ja.d1 * a - jb.d1 * b) / (ja.d1 - jb.d1);
      inside = next > a && next < b;
    }
    if (!inside || slow >= 3) next = (a + b) / R(2), slow = 0;
    x = next;
  }
  return best;
}

// Minimum of f over the circle. `radius` is the circle's radius (the Lipschitz constant per
// radian), `best` a value the caller already has (refinement is skipped where it cannot win),
// `stop_below` ends the search as soon as a value below it is found, `tol` the absolute error.
// `between_samples`: also search the intervals between samples that the Lipschitz bound
// (f_k + f_k+1 - r h) / 2 cannot clear. One can hold a basin narrower than the spacing that no
// discrete minimum leads to (two minima 0.4 rad apart, only the shallower one a discrete minimum
// of the samples): sampled 8 times finer, those samples' discrete minima refined by Brent. The
// circle distances take it; the solid-cylinder kernel does not, as its time with it is not
// measured yet and against FCL it has shown no miss (experiments/ci/README.md).
template <class R, class F>
CircleMin<R> minimize_on_circle(F&& f, R radius, R best, R stop_below, R tol, bool between_samples = false) {
  const auto& table = circle_sample_table<R>();
  std::array<R, kCircleSamples> fs;
  if constexpr (requires { f.sample(table.cos, table.sin, fs); }) {
    f.sample(table.cos, table.sin, fs);
  } else {
    for (int k = 0; k < kCircleSamples; ++k) fs[k] = f(table.cos[k], table.sin[k]);
  }
  int kmin = 0;
  for (int k = 1; k < kCircleSamples; ++k)
    if (fs[k] < fs[kmin]) kmin = k;
  CircleMin<R> result{fs[kmin], table.cos[kmin], table.sin[kmin]};
  if (result.value < stop_below) return result;

  const R h = R(2) * R(3.14159265358979323846264338327950288L) / R(kCircleSamples);
  const R slack = radius * h;  // f can dip at most this far below a sample within +-h
  if (radius <= R(0) || !(fs[kmin] - slack < min_(best, result.value))) return result;
  const R xtol = max_(tol / radius, R(4) * Limits<R>::epsilon());
  const int max_iter = 200;

  // Refine discrete local minima, lowest first.
  std::array<int, kCircleSamples> order;
  int n = 0;
  for (int k = 0; k < kCircleSamples; ++k) {
    const R prev = fs[(k + kCircleSamples - 1) % kCircleSamples];
    const R next = fs[(k + 1) % kCircleSamples];
    // A plateau counts once: strictly below the previous sample, not above the next.
    if (fs[k] < prev && fs[k] <= next) order[n++] = k;
  }
  if (n == 0) order[n++] = kmin;  // constant function
  std::sort(order.begin(), order.begin() + n, [&](int i, int j) { return fs[i] < fs[j]; });
  for (int i = 0; i < n; ++i) {
    const int k = order[i];
    if (!(fs[k] - slack < min_(best, result.value))) break;
    const R x = h * R(k);
    CircleMin<R> m;
    if constexpr (requires { f.jet(R(0), R(0)); }) {
      const int ka = (k + kCircleSamples - 1) % kCircleSamples, kb = (k + 1) % kCircleSamples;
      auto end_jets = [&](Jet<R>* ja, Jet<R>* jb) {
        *ja = f.jet(table.cos[ka], table.sin[ka]);
        *jb = f.jet(table.cos[kb], table.sin[kb]);
      };
      m = newton_on_angle<R>(f, x - h, x + h, x, end_jets, tol, xtol, max_iter);
    } else {
      m = brent_on_angle<R>(f, x - h, x + h, x, fs[k], xtol, max_iter);
    }
    if (m.value < result.value) result = m;
    if (result.value < stop_below) return result;
  }
  if (!between_samples) return result;
  constexpr int kFiner = 8;
  const R hf = h / R(kFiner);
  for (int k = 0; k < kCircleSamples; ++k) {
    const R fa = fs[k], fb = fs[(k + 1) % kCircleSamples];
    if (!((fa + fb - slack) / R(2) < min_(best, result.value) - tol)) continue;
    std::array<R, kFiner + 1> g;
    g[0] = fa, g[kFiner] = fb;
    for (int j = 1; j < kFiner; ++j) {
      R si, co;
      sincos_(h * R(k) + hf * R(j), &si, &co);
      g[j] = f(co, si);
      if (g[j] < result.value) result = {g[j], co, si};
    }
    for (int j = 1; j < kFiner; ++j) {
      if (!(g[j] < g[j - 1] && g[j] <= g[j + 1])) continue;
      const R x = h * R(k) + hf * R(j);
      const CircleMin<R> m = brent_on_angle<R>(f, x - hf, x + hf, x, g[j], xtol, max_iter);
      if (m.value < result.value) result = m;
    }
  }
  return result;
}

}  // namespace mtcs::geometry::detail
