// The line-sink tiers' hot loop: the fields of one channel's elements at many points in single
// precision, vectorised over the points (AVX2 when the CPU has it). Per point, the nodes between
// elements are shared: M + 1 square roots and 2 (M + 1) reciprocals for M elements, not 2 M and
// 4 M. With slot weights the image points of each target are summed on the fly, so no
// points x columns buffer is written and read back.

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#include "thermal/kernels/line_sink_fields.h"
#include "thermal/kernels/cpu_features.h"

namespace mtcs::thermal {

namespace {

// log x for 1 <= x < 2^127, branch-free so that loops over it vectorise: x = m 2^e with m in
// [sqrt(1/2), sqrt(2)), log m = 2 atanh((m - 1)/(m + 1)) to f^9 (error below 4e-10).
inline float log_float(float x) {
  const std::int32_t bits = std::bit_cast<std::int32_t>(x);
  std::int32_t e = ((bits >> 23) & 0xff) - 127;
  float m = std::bit_cast<float>((bits & 0x007fffff) | 0x3f800000);
  const std::int32_t big = m > 1.41421356f ? 1 : 0;
  m = big ? 0.5f * m : m;
  e += big;
  const float f = (m - 1) / (m + 1), f2 = f * f;
  const float p = 1 + f2 * (1.0f / 3 + f2 * (1.0f / 5 + f2 * (1.0f / 7 + f2 * (1.0f / 9))));
  return float(e) * 0.69314718f + 2 * f * p;
}

struct FloatAxis {
  float ax, ay, az, ux, uy, uz, n1x, n1y, n1z, n2x, n2y, n2z;
};

// All M elements' sink (and dipole) potentials at n points; no branch but selects, the element
// loop unrolled (M is a constant) so that the point loop vectorises. node[i]: the axial position
// of node i from the axis' start (node[M] = the length). out[c * out_stride + i] = value, or
// with Accumulate += w[i] * value (one slot of the slot layout: every target's j-th image).
template <int M, bool Dipoles, bool Accumulate>
[[gnu::always_inline]] inline void elements_float(const FloatAxis g, const float* node, const float* __restrict x,
                           const float* __restrict y, const float* __restrict z, const float* __restrict w,
                           std::size_t n, float* __restrict out, std::size_t out_stride) {
  constexpr int kinds = Dipoles ? 3 : 1;
  float s[M + 1], len2[M];
  for (int e = 0; e <= M; ++e) s[e] = node[e];
  for (int e = 0; e < M; ++e) len2[e] = 2 * (node[e + 1] - node[e]);
  // The columns of out are disjoint ranges: no dependence between points (no alias checks).
#pragma GCC ivdep
  for (std::size_t i = 0; i < n; ++i) {
    const float wx = x[i] - g.ax, wy = y[i] - g.ay, wz = z[i] - g.az;
    const float t0 = wx * g.ux + wy * g.uy + wz * g.uz;
    const float rx = wx - t0 * g.ux, ry = wy - t0 * g.uy, rz = wz - t0 * g.uz;
    const float rho2 = rx * rx + ry * ry + rz * rz;
    const float inv_rho2 = 1 / rho2;
    const float c1 = rx * g.n1x + ry * g.n1y + rz * g.n1z, c2 = rx * g.n2x + ry * g.n2y + rz * g.n2z;
    // Node a of the first element; then each element's node b becomes the next one's a.
    float ta = t0 - s[0];
    float ra = std::sqrt(rho2 + ta * ta);
    float pa = ra + std::abs(ta);
    float inv = 1 / (pa * ra);  // one division for both reciprocals
    float ipa = ra * inv, ira = pa * inv;
    // With weights, the weight joins rho . n once per point rather than each dipole per element.
    const float wi = Accumulate ? w[i] : 1.0f, wc1 = wi * c1, wc2 = wi * c2;
#pragma GCC unroll 16
    for (int e = 0; e < M; ++e) {
      const float tb = t0 - s[e + 1];
      const float rb = std::sqrt(rho2 + tb * tb);
      // r + |t| and its reciprocal serve both kernels: r - t = rho^2/(r + t) when t > 0.
      const float pb = rb + std::abs(tb);
      const float invb = 1 / (pb * rb);
      const float ipb = rb * invb, irb = pb * invb;
      const float A = ta > 0 ? rho2 * ipa : pa;
      const float B = tb < 0 ? rho2 * ipb : pb;
      const float D = A + B;
      float v[3];
      v[0] = log_float((D + len2[e]) / D);
      if constexpr (Dipoles) {
        // (ta/ra - tb/rb)/rho^2 in the cancellation-free forms of element_fields.
        const float ca = ipa * ira, cb = ipb * irb;
        const float across = (ta * ira - tb * irb) * inv_rho2;
        const float factor = tb >= 0 ? cb - ca : (ta <= 0 ? ca - cb : across);
        v[1] = factor * (Accumulate ? wc1 : c1);
        v[2] = factor * (Accumulate ? wc2 : c2);
      }
#pragma GCC unroll 3
      for (int k = 0; k < kinds; ++k) {
        float& o = out[std::size_t(e * kinds + k) * out_stride + i];
        if constexpr (Accumulate) o += k == 0 ? wi * v[k] : v[k];
        else o = v[k];
      }
      ta = tb, ra = rb, pa = pb, ipa = ipb, ira = irb;
    }
  }
}

// The same fields at points far from every element (each element's centre at least its half
// length h / far_ratio away): the multipole expansion of each element about its centre, to
// the P6 term. With q = h / d <= far_ratio, d the distance to the element's centre and c the
// cosine of the angle to the axis there (Legendre P_n, Gegenbauer C_n = C^(3/2)_n):
//   sink   integral dl / r   = (2h/d)   sum_n q^n P_n(c) / (n + 1),  n even,
//   dipole integral dl / r^3 = (2h/d^3) sum_n q^n C_n(c) / (n + 1),  n even (then times rho . n).
// Truncated after n = 6, the relative error is below q^8/9 / (1 - q^2) for the sink and
// 5 q^8 / (1 - q^2) for the dipole (|P_n| <= 1, |C_n| <= (n + 1)(n + 2) / 2): at q = 0.3,
// 7e-6 and 4e-4. One division and one square root per element, no log, no select.
template <int M, bool Dipoles>
[[gnu::always_inline]] inline void elements_far(const FloatAxis g, const float* node, const float* __restrict x,
                                                const float* __restrict y, const float* __restrict z,
                                                const float* __restrict w, std::size_t n, float* __restrict out,
                                                std::size_t out_stride) {
  constexpr int kinds = Dipoles ? 3 : 1;
  float mid[M], h2[M], two_h[M];
  for (int e = 0; e < M; ++e) {
    mid[e] = 0.5f * (node[e] + node[e + 1]);
    const float h = 0.5f * (node[e + 1] - node[e]);
    h2[e] = h * h, two_h[e] = 2 * h;
  }
#pragma GCC ivdep
  for (std::size_t i = 0; i < n; ++i) {
    const float wx = x[i] - g.ax, wy = y[i] - g.ay, wz = z[i] - g.az;
    const float t0 = wx * g.ux + wy * g.uy + wz * g.uz;
    const float rx = wx - t0 * g.ux, ry = wy - t0 * g.uy, rz = wz - t0 * g.uz;
    const float rho2 = rx * rx + ry * ry + rz * rz;
    const float c1 = rx * g.n1x + ry * g.n1y + rz * g.n1z, c2 = rx * g.n2x + ry * g.n2y + rz * g.n2z;
    const float wi = w[i], wc1 = wi * c1, wc2 = wi * c2;
#pragma GCC unroll 16
    for (int e = 0; e < M; ++e) {
      const float tau = t0 - mid[e], tau2 = tau * tau;
      const float id2 = 1 / (rho2 + tau2), id = std::sqrt(id2);
      const float q2 = h2[e] * id2, cc = tau2 * id2;  // q^2 and c^2
      // P2/3, P4/5, P6/7 as polynomials in c^2, their constant factors folded in.
      const float p2 = 0.5f * cc - (1.0f / 6);
      const float p4 = (0.875f * cc - 0.75f) * cc + 0.075f;
      const float p6 = ((2.0625f * cc - 2.8125f) * cc + 0.9375f) * cc - (5.0f / 112);
      const float g = two_h[e] * id;
      out[std::size_t(e * kinds) * out_stride + i] += wi * (g * (1 + q2 * (p2 + q2 * (p4 + q2 * p6))));
      if constexpr (Dipoles) {
        // C2/3, C4/5, C6/7 likewise; the weight and rho . n taken per point.
        const float d2 = 2.5f * cc - 0.5f;
        const float d4 = (7.875f * cc - 5.25f) * cc + 0.375f;
        const float d6 = ((26.8125f * cc - 30.9375f) * cc + 8.4375f) * cc - 0.3125f;
        const float factor = g * id2 * (1 + q2 * (d2 + q2 * (d4 + q2 * d6)));
        out[std::size_t(e * kinds + 1) * out_stride + i] += factor * wc1;
        out[std::size_t(e * kinds + 2) * out_stride + i] += factor * wc2;
      }
    }
  }
}

// Any element count: one element at a time (the nodes recomputed per element).
template <bool Dipoles, bool Accumulate>
[[gnu::always_inline]] inline void elements_float_any(const FloatAxis& g, int m, const float* node, const float* x, const float* y,
                        const float* z, const float* w, std::size_t n, float* out, std::size_t out_stride) {
  constexpr int kinds = Dipoles ? 3 : 1;
  for (int e = 0; e < m; ++e) {
    const float pair[2] = {0, node[e + 1] - node[e]};
    FloatAxis shifted = g;
    shifted.ax += node[e] * g.ux, shifted.ay += node[e] * g.uy, shifted.az += node[e] * g.uz;
    elements_float<1, Dipoles, Accumulate>(shifted, pair, x, y, z, w, n,
                                           out + std::size_t(e * kinds) * out_stride, out_stride);
  }
}

// Inlined into each target clone below, so that the AVX2 clone gets AVX2 loops.
template <bool Accumulate>
[[gnu::always_inline]] inline void dispatch(const FloatAxis& g, int m, int kinds, const float* node, const float* x, const float* y,
              const float* z, const float* w, std::size_t n, float* out, std::size_t out_stride) {
#define MTCS_ELEMENTS(M)                                                                      \
  case M:                                                                                     \
    if (kinds == 3) elements_float<M, true, Accumulate>(g, node, x, y, z, w, n, out, out_stride); \
    else elements_float<M, false, Accumulate>(g, node, x, y, z, w, n, out, out_stride);       \
    return;
  switch (m) {
    MTCS_ELEMENTS(1)
    MTCS_ELEMENTS(2)
    MTCS_ELEMENTS(3)
    MTCS_ELEMENTS(4)
    MTCS_ELEMENTS(6)
    MTCS_ELEMENTS(8)
    MTCS_ELEMENTS(12)
    default: break;
  }
#undef MTCS_ELEMENTS
  if (kinds == 3) elements_float_any<true, Accumulate>(g, m, node, x, y, z, w, n, out, out_stride);
  else elements_float_any<false, Accumulate>(g, m, node, x, y, z, w, n, out, out_stride);
}

// The far expansion for the element counts the exact kernel unrolls; false: not available.
[[gnu::always_inline]] inline bool dispatch_far(const FloatAxis& g, int m, int kinds, const float* node, const float* x,
                                                const float* y, const float* z, const float* w, std::size_t n,
                                                float* out, std::size_t out_stride) {
#define MTCS_FAR(M)                                                                        \
  case M:                                                                                  \
    if (kinds == 3) elements_far<M, true>(g, node, x, y, z, w, n, out, out_stride);         \
    else elements_far<M, false>(g, node, x, y, z, w, n, out, out_stride);                   \
    return true;
  switch (m) {
    MTCS_FAR(1)
    MTCS_FAR(2)
    MTCS_FAR(3)
    MTCS_FAR(4)
    MTCS_FAR(6)
    MTCS_FAR(8)
    MTCS_FAR(12)
    default: return false;
  }
#undef MTCS_FAR
}

// Each element's centre (x, y, z) and the squared distance (h / far_ratio)^2 beyond which the
// far expansion holds: 4 floats per element.
inline void far_limits(const FloatAxis& g, int m, const float* node, float far_ratio, float* out) {
  for (int e = 0; e < m; ++e) {
    const float mid = 0.5f * (node[e] + node[e + 1]), h = 0.5f * (node[e + 1] - node[e]);
    out[4 * e] = g.ax + mid * g.ux, out[4 * e + 1] = g.ay + mid * g.uy, out[4 * e + 2] = g.az + mid * g.uz;
    out[4 * e + 3] = (h / far_ratio) * (h / far_ratio);
  }
}

// Is every point of the box (min x, y, z, max x, y, z) far from every element (far_limits)?
inline bool chunk_is_far(int m, const float* limits, const float* box) {
  for (int e = 0; e < m; ++e) {
    const float* c = limits + 4 * e;
    float d2 = 0;
    for (int a = 0; a < 3; ++a) {
      const float gap = std::max({box[a] - c[a], c[a] - box[3 + a], 0.0f});
      d2 += gap * gap;
    }
    if (!(d2 >= c[3])) return false;
  }
  return true;
}

FloatAxis float_axis(const ChannelAxis& axis, const Vec3& origin, std::vector<float>& node) {
  const Vec3 a = axis.p0 - origin;
  node.resize(axis.elements + 1);
  for (int e = 0; e < axis.elements; ++e) node[e] = float(e * axis.element_length);
  node[axis.elements] = float(axis.length);
  return {float(a.x()),       float(a.y()),       float(a.z()),       float(axis.u.x()),
          float(axis.u.y()),  float(axis.u.z()),  float(axis.n1.x()), float(axis.n1.y()),
          float(axis.n1.z()), float(axis.n2.x()), float(axis.n2.y()), float(axis.n2.z())};
}

}  // namespace

// Each entry point compiled twice, for AVX2 with FMA and for the baseline, picked at run time
// (target_clones cannot ask for two features at once). The nodes and far limits are per-thread
// scratch: an optimiser's solve calls these some 25 times, each a malloc and free otherwise.
#define MTCS_FIELDS_BODY                                                                   \
  thread_local std::vector<float> node;                                                    \
  const FloatAxis g = float_axis(axis, origin, node);                                      \
  dispatch<false>(g, axis.elements, kinds, node.data(), x, y, z, nullptr, n, out, n);
// Per slot, runs of chunks that are all far (or all near) go to one kernel each.
#define MTCS_SLOTS_BODY                                                                     \
  thread_local std::vector<float> node, limits;                                             \
  const FloatAxis g = float_axis(axis, origin, node);                                       \
  const std::size_t chunk = far ? far->chunk : targets;                                     \
  const std::size_t chunks = chunk ? (targets + chunk - 1) / chunk : 0;                     \
  limits.resize(far ? 4 * axis.elements : 0);                                               \
  if (far) far_limits(g, axis.elements, node.data(), far->ratio, limits.data());            \
  for (int j = 0; j < slots; ++j) {                                                         \
    const std::size_t k = std::size_t(j) * targets;                                         \
    for (std::size_t c0 = 0; c0 < chunks;) {                                                \
      const auto is_far = [&](std::size_t c) {                                              \
        return far && chunk_is_far(axis.elements, limits.data(), far->box + 6 * (j * chunks + c)); \
      };                                                                                    \
      const bool run_far = is_far(c0);                                                      \
      std::size_t c1 = c0 + 1;                                                              \
      while (c1 < chunks && is_far(c1) == run_far) ++c1;                                    \
      const std::size_t b = c0 * chunk, n = std::min(c1 * chunk, targets) - b;              \
      if (!run_far || !dispatch_far(g, axis.elements, kinds, node.data(), x + k + b, y + k + b, z + k + b, \
                                    w + k + b, n, out + b, targets))                        \
        dispatch<true>(g, axis.elements, kinds, node.data(), x + k + b, y + k + b, z + k + b, w + k + b, n, \
                       out + b, targets);                                                   \
      c0 = c1;                                                                              \
    }                                                                                       \
  }

namespace {

__attribute__((target("avx2,fma"))) void fields_avx2(const ChannelAxis& axis, const Vec3& origin, int kinds,
                                                     const float* x, const float* y, const float* z,
                                                     std::size_t n, float* out) {
  MTCS_FIELDS_BODY
}
void fields_base(const ChannelAxis& axis, const Vec3& origin, int kinds, const float* x, const float* y,
                 const float* z, std::size_t n, float* out) {
  MTCS_FIELDS_BODY
}
__attribute__((target("avx2,fma"))) void slots_avx2(const ChannelAxis& axis, const Vec3& origin, int kinds,
                                                    const float* x, const float* y, const float* z,
                                                    const float* w, std::size_t targets, int slots, float* out,
                                                    const FarChunks* far) {
  MTCS_SLOTS_BODY
}
void slots_base(const ChannelAxis& axis, const Vec3& origin, int kinds, const float* x, const float* y,
                const float* z, const float* w, std::size_t targets, int slots, float* out,
                                                    const FarChunks* far) {
  MTCS_SLOTS_BODY
}

#define MTCS_ACCUMULATE_BODY                                                        \
  constexpr std::size_t kChunk = 256;                                               \
  double acc[kChunk];                                                               \
  for (std::size_t s0 = 0; s0 < n; s0 += kChunk) {                                  \
    const std::size_t len = std::min(kChunk, n - s0);                               \
    for (std::size_t i = 0; i < len; ++i) acc[i] = T[s0 + i];                       \
    for (int c = 0; c < ncols; ++c) {                                               \
      const double xc = x[c];                                                       \
      const float* v = cols + std::size_t(c) * n + s0;                              \
      for (std::size_t i = 0; i < len; ++i) acc[i] += xc * double(v[i]);            \
    }                                                                               \
    for (std::size_t i = 0; i < len; ++i) T[s0 + i] = acc[i];                       \
  }
__attribute__((target("avx2,fma"))) void accumulate_avx2(const float* cols, std::size_t n, int ncols,
                                                         const double* x, double* T) {
  MTCS_ACCUMULATE_BODY
}
void accumulate_base(const float* cols, std::size_t n, int ncols, const double* x, double* T) {
  MTCS_ACCUMULATE_BODY
}
#undef MTCS_ACCUMULATE_BODY

}  // namespace

void accumulate_float_columns(const float* cols, std::size_t n, int ncols, const double* x, double* T) {
  if (has_avx2_fma()) accumulate_avx2(cols, n, ncols, x, T);
  else accumulate_base(cols, n, ncols, x, T);
}

void element_fields_float(const ChannelAxis& axis, const Vec3& origin, int kinds, const float* x,
                          const float* y, const float* z, std::size_t n, float* out) {
  if (has_avx2_fma()) fields_avx2(axis, origin, kinds, x, y, z, n, out);
  else fields_base(axis, origin, kinds, x, y, z, n, out);
}

void element_fields_float_slots(const ChannelAxis& axis, const Vec3& origin, int kinds, const float* x,
                                const float* y, const float* z, const float* w, std::size_t targets,
                                int slots, float* out, const FarChunks* far) {
  if (has_avx2_fma()) slots_avx2(axis, origin, kinds, x, y, z, w, targets, slots, out, far);
  else slots_base(axis, origin, kinds, x, y, z, w, targets, slots, out, far);
}

}  // namespace mtcs::thermal
