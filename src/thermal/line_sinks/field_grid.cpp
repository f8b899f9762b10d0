// FieldGrid's tricubic lookup: a few per wall point of every rebuilt channel (heat input, faces,
// far lattice), ~15 % of an ES child on the plate. The field count is a template constant for
// the grids the model builds (1, 2, 4, 5, 6), so the per-node sum over fields unrolls and
// vectorises; compiled for AVX2/FMA too, picked at run time.

#include "thermal/line_sinks/line_sink_tables.h"
#include "thermal/kernels/cpu_features.h"

namespace mtcs::thermal {

namespace {

struct Stencil {
  std::size_t base[16];  // first node (x) of each of the 4 x 4 rows (y, z), times the fields
  double wx[4], wyz[16];
};

inline Stencil stencil(const FieldGrid& g, const Vec3& p) {
  std::array<int, 3> i0;
  std::array<std::array<double, 4>, 3> w;
  for (int a = 0; a < 3; ++a) {
    const double u = (p[a] - g.origin[a]) / g.step[a];
    i0[a] = std::clamp(int(std::floor(u)) - 1, 0, g.nodes[a] - 4);
    const double t = u - i0[a];  // stencil nodes at 0, 1, 2, 3 (4-point Lagrange)
    w[a] = {-(t - 1) * (t - 2) * (t - 3) / 6, t * (t - 2) * (t - 3) / 2, -t * (t - 1) * (t - 3) / 2,
            t * (t - 1) * (t - 2) / 6};
  }
  Stencil s;
  for (int i = 0; i < 4; ++i) s.wx[i] = w[0][i];
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 4; ++j) {
      s.wyz[4 * k + j] = w[1][j] * w[2][k];
      s.base[4 * k + j] =
          ((std::size_t(i0[2] + k) * std::size_t(g.nodes[1]) + std::size_t(i0[1] + j)) * std::size_t(g.nodes[0]) +
           std::size_t(i0[0])) * std::size_t(g.fields);
    }
  return s;
}

// F > 0: the field count as a constant (the sum over fields unrolls and vectorises); 0: `fields`.
template <int F>
[[gnu::always_inline]] inline void sum(const Stencil& s, const double* __restrict values, int fields,
                                       double* __restrict out) {
  const int nf = F > 0 ? F : fields;
  std::fill(out, out + nf, 0.0);
  for (int r = 0; r < 16; ++r) {
    const double* v = values + s.base[r];
    for (int i = 0; i < 4; ++i) {
      const double wt = s.wx[i] * s.wyz[r];
      for (int f = 0; f < nf; ++f) out[f] += wt * v[i * nf + f];
    }
  }
}

#define MTCS_INTERPOLATE_BODY                                    \
  const Stencil s = stencil(g, p);                               \
  const double* v = g.values.data();                             \
  switch (g.fields) {                                            \
    case 1: return sum<1>(s, v, 1, out);                         \
    case 2: return sum<2>(s, v, 2, out);                         \
    case 4: return sum<4>(s, v, 4, out);                         \
    case 5: return sum<5>(s, v, 5, out);                         \
    case 6: return sum<6>(s, v, 6, out);                         \
    default: return sum<0>(s, v, g.fields, out);                 \
  }

__attribute__((target("avx2,fma"))) void interpolate_avx2(const FieldGrid& g, const Vec3& p, double* out) {
  MTCS_INTERPOLATE_BODY
}
void interpolate_base(const FieldGrid& g, const Vec3& p, double* out) { MTCS_INTERPOLATE_BODY }
#undef MTCS_INTERPOLATE_BODY

}  // namespace

void FieldGrid::interpolate(const Vec3& p, double* out) const {
  if (has_avx2_fma()) interpolate_avx2(*this, p, out);
  else interpolate_base(*this, p, out);
}

}  // namespace mtcs::thermal
