// The far-field multipole of a channel's elements (element_far_fields.h), vectorised over the
// targets of a slot: one square root and one division per point and element (the exact kernel: ~1.25 roots
// and ~3 divisions and a logarithm). Compiled for AVX2 with FMA and for the baseline, picked at
// run time as element_fields_float.cpp.

#include "element_far_fields.h"

#include <cmath>

namespace mtcs::thermal {

namespace {

struct Element {
  float cx, cy, cz;  // midpoint relative to the origin
};

template <bool Dipoles>
[[gnu::always_inline]] inline void far_element(const Element c, const float* axis, float L, const float* __restrict x,
                                               const float* __restrict y, const float* __restrict z,
                                               const float* __restrict w, std::size_t n, float* __restrict phi,
                                               float* __restrict d1, float* __restrict d2) {
  const float ux = axis[0], uy = axis[1], uz = axis[2];
  const float n1x = axis[3], n1y = axis[4], n1z = axis[5], n2x = axis[6], n2y = axis[7], n2z = axis[8];
  const float q = L * L / 24;
#pragma GCC ivdep
  for (std::size_t i = 0; i < n; ++i) {
    const float dx = x[i] - c.cx, dy = y[i] - c.cy, dz = z[i] - c.cz;
    const float r2 = dx * dx + dy * dy + dz * dz;
    const float ir2 = 1 / r2, ir = std::sqrt(ir2);
    const float tau = dx * ux + dy * uy + dz * uz;
    const float t2 = tau * tau * ir2;  // cos^2 of the angle to the axis
    const float wl = w[i] * L * ir;
    phi[i] += wl * (1 + q * ir2 * (3 * t2 - 1));
    if constexpr (Dipoles) {
      const float f = wl * ir2 * (1 + q * ir2 * (15 * t2 - 3));
      d1[i] += f * (dx * n1x + dy * n1y + dz * n1z);
      d2[i] += f * (dx * n2x + dy * n2y + dz * n2z);
    }
  }
}

#define MTCS_FAR_BODY                                                                             \
  const float frame[9] = {float(axis.u.x()),  float(axis.u.y()),  float(axis.u.z()),             \
                          float(axis.n1.x()), float(axis.n1.y()), float(axis.n1.z()),            \
                          float(axis.n2.x()), float(axis.n2.y()), float(axis.n2.z())};           \
  const float L = float(axis.element_length);                                                    \
  for (int e = 0; e < axis.elements; ++e) {                                                      \
    const Vec3 m = axis.p0 + ((e + 0.5) * axis.element_length) * axis.u - origin;               \
    const Element c{float(m.x()), float(m.y()), float(m.z())};                                   \
    float* o = out + std::size_t(e * kinds) * targets;                                           \
    for (int j = 0; j < slots; ++j) {                                                            \
      const std::size_t k = std::size_t(j) * targets;                                            \
      if (kinds == 3) far_element<true>(c, frame, L, x + k, y + k, z + k, w + k, targets, o, o + targets, o + 2 * targets); \
      else far_element<false>(c, frame, L, x + k, y + k, z + k, w + k, targets, o, nullptr, nullptr); \
    }                                                                                            \
  }

bool has_avx2_fma() {
  static const bool yes = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  return yes;
}

__attribute__((target("avx2,fma"))) void far_avx2(const ChannelAxis& axis, const Vec3& origin, int kinds,
                                                  const float* x, const float* y, const float* z, const float* w,
                                                  std::size_t targets, int slots, float* out) {
  MTCS_FAR_BODY
}
void far_base(const ChannelAxis& axis, const Vec3& origin, int kinds, const float* x, const float* y,
              const float* z, const float* w, std::size_t targets, int slots, float* out) {
  MTCS_FAR_BODY
}

}  // namespace

void element_far_fields_float_slots(const ChannelAxis& axis, const Vec3& origin, int kinds, const float* x,
                                    const float* y, const float* z, const float* w, std::size_t targets, int slots,
                                    float* out) {
  if (has_avx2_fma()) far_avx2(axis, origin, kinds, x, y, z, w, targets, slots, out);
  else far_base(axis, origin, kinds, x, y, z, w, targets, slots, out);
}

}  // namespace mtcs::thermal
