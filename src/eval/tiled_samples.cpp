#include "tiled_samples.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>
#include <span>

namespace mtcs::eval {
namespace {

using geometry::Vec3;
constexpr std::size_t kTile = TiledSamples::kTile;

// One bore over one tile: m_i = min(m_i, |p_i - segment|^2) in single precision (the expression
// of the plain loop it stands for). Returns the tile's largest m_i afterwards. A fixed count: the
// loops vectorise whole. kAxis = 0, 1, 2: the segment lies along that axis (its other two
// components are zero), and the terms with them, zeros that change no bit of d2, are left out: a
// third fewer operations for the axis-parallel bores most molds drill. -1: any segment.
template <int kAxis>
[[gnu::always_inline]] inline float score_bore(const float* __restrict xs, const float* __restrict ys,
                                              const float* __restrict zs, const float a[3], const float d[3],
                                              float inv, float* __restrict m) {
  const float ax = a[0], ay = a[1], az = a[2], dx = d[0], dy = d[1], dz = d[2];
  for (std::size_t i = 0; i < kTile; ++i) {
    const float px = xs[i] - ax, py = ys[i] - ay, pz = zs[i] - az;
    float d2;
    if constexpr (kAxis < 0) {
      float t = (px * dx + py * dy + pz * dz) * inv;
      t = std::min(std::max(t, 0.f), 1.f);  // t < 0 ? 0 : (t > 1 ? 1 : t), NaN and -0 included
      const float qx = px - t * dx, qy = py - t * dy, qz = pz - t * dz;
      d2 = qx * qx + qy * qy + qz * qz;
    } else {
      // p_a d_a is the dot product up to the sign of a zero, which the clamp and the square
      // make no difference to; q = p off the axis.
      const float pa = kAxis == 0 ? px : kAxis == 1 ? py : pz, da = kAxis == 0 ? dx : kAxis == 1 ? dy : dz;
      float t = (pa * da) * inv;
      t = std::min(std::max(t, 0.f), 1.f);
      const float qa = pa - t * da;
      const float qx = kAxis == 0 ? qa : px, qy = kAxis == 1 ? qa : py, qz = kAxis == 2 ? qa : pz;
      d2 = qx * qx + qy * qy + qz * qz;
    }
    m[i] = d2 < m[i] ? d2 : m[i];
  }
  // The largest, eight lanes at a time (a loop-carried maximum would not vectorise).
  using Lanes = float __attribute__((vector_size(32)));
  Lanes top, next;
  std::memcpy(&top, m, sizeof top);
  for (std::size_t i = 8; i < kTile; i += 8) {
    std::memcpy(&next, m + i, sizeof next);
    top = next > top ? next : top;
  }
  float largest = top[0];
  for (int k = 1; k < 8; ++k) largest = top[k] > largest ? top[k] : largest;
  return largest;
}

// Per bore, the least distance a sample of the tile can have to it, less its rounding margin:
// max(0, gap - margin_b - tile_margin), gap = the distance between the tile's box and the bore's.
// Its square is what a tile's largest distance so far is compared with: no root in that chain.
[[gnu::always_inline]] inline void box_gaps(const double* lo[3], const double* hi[3], const double* margin,
                                            const double tlo[3], const double thi[3], double tile_margin,
                                            std::size_t n, double* __restrict gap2) {
  for (std::size_t b = 0; b < n; ++b) {
    double sum = 0;
    for (int k = 0; k < 3; ++k) {
      const double below = lo[k][b] - thi[k], above = tlo[k] - hi[k][b];
      const double g = below > above ? below : above;
      sum += g > 0 ? g * g : 0;
    }
    const double near = std::sqrt(sum) - margin[b] - tile_margin;
    gap2[b] = near > 0 ? near * near : 0;
  }
}

// Splits [first, last) of `order` across the longest side of its box, the first part a whole
// number of tiles, until one tile is left: compact tiles, whatever the cavity's shape.
void split(std::vector<std::uint32_t>& order, std::size_t first, std::size_t last, const float* xyz[3],
           std::vector<std::pair<std::size_t, std::size_t>>& leaves) {
  if (last - first <= kTile) {
    leaves.push_back({first, last});
    return;
  }
  float lo[3], hi[3];
  for (int k = 0; k < 3; ++k) lo[k] = hi[k] = xyz[k][order[first]];
  for (std::size_t i = first; i < last; ++i)
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], xyz[k][order[i]]), hi[k] = std::max(hi[k], xyz[k][order[i]]);
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (hi[k] - lo[k] > hi[axis] - lo[axis]) axis = k;
  const std::size_t tiles = (last - first + kTile - 1) / kTile, mid = first + (tiles + 1) / 2 * kTile;
  const float* v = xyz[axis];
  std::nth_element(order.begin() + long(first), order.begin() + long(mid), order.begin() + long(last),
                   [v](std::uint32_t i, std::uint32_t j) { return v[i] < v[j] || (v[i] == v[j] && i < j); });
  split(order, first, mid, xyz, leaves);
  split(order, mid, last, xyz, leaves);
}

// Bores as the tiles use them: the single-precision segment (a, d, 1 / |d|^2), its box and the
// part of the rounding margin it brings. Per thread: no allocation per evaluation.
struct Bores {
  std::vector<std::array<float, 7>> segment;
  std::vector<int> axis;  // the axis a segment lies along, -1: none
  std::vector<double> lo[3], hi[3], margin, gap2;
};

// Every tile's m (TiledSamples::nearest_squared): one call, compiled for AVX2 where the CPU has
// it, with the per-bore kernels inlined.
__attribute__((target_clones("avx2", "default"))) void score_tiles(const TiledSamples::Tile* tiles,
                                                                   std::size_t count, const float* xs,
                                                                   const float* ys, const float* zs, Bores& s,
                                                                   float* m) {
  const std::size_t nb = s.segment.size();
  const double* lo[3] = {s.lo[0].data(), s.lo[1].data(), s.lo[2].data()};
  const double* hi[3] = {s.hi[0].data(), s.hi[1].data(), s.hi[2].data()};
  for (const TiledSamples::Tile& tile : std::span(tiles, count)) {
    float* tm = m + tile.begin;
    std::fill_n(tm, kTile, std::numeric_limits<float>::infinity());
    if (nb == 0) continue;
    const double tlo[3] = {tile.lo.x(), tile.lo.y(), tile.lo.z()}, thi[3] = {tile.hi.x(), tile.hi.y(), tile.hi.z()};
    box_gaps(lo, hi, s.margin.data(), tlo, thi, tile.margin, nb, s.gap2.data());
    // A computed distance is at least max(0, gap - margin) (1 - 1e-6), gap = the distance between
    // the boxes: the margin covers the single-precision rounding (~2e-7 of the coordinates) 50
    // times over. A bore with gap - margin > reach cannot lower an m_i; compared in squares,
    // reach^2 = the tile's largest m_i (1 + 2e-6) >= largest / (1 - 1e-6): no division either.
    auto score = [&](std::size_t b) __attribute__((always_inline)) {
      const auto& f = s.segment[b];
      const float *x = xs + tile.begin, *y = ys + tile.begin, *z = zs + tile.begin;
      float largest;
      switch (s.axis[b]) {
        case 0: largest = score_bore<0>(x, y, z, f.data(), f.data() + 3, f[6], tm); break;
        case 1: largest = score_bore<1>(x, y, z, f.data(), f.data() + 3, f[6], tm); break;
        case 2: largest = score_bore<2>(x, y, z, f.data(), f.data() + 3, f[6], tm); break;
        default: largest = score_bore<-1>(x, y, z, f.data(), f.data() + 3, f[6], tm);
      }
      return double(largest) * (1 + 2e-6);
    };
    const std::size_t lead = std::size_t(std::min_element(s.gap2.begin(), s.gap2.begin() + long(nb)) - s.gap2.begin());
    double reach2 = score(lead);
    for (std::size_t b = 0; b < nb; ++b)
      if (b != lead && s.gap2[b] <= reach2) reach2 = score(b);
  }
}

}  // namespace

TiledSamples::TiledSamples(const SurfaceSamples& samples, const Vec3& origin) : origin_(origin) {
  const std::size_t n = samples.size();
  std::vector<float> x(n), y(n), z(n);
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = float(samples.x[i] - origin.x());
    y[i] = float(samples.y[i] - origin.y());
    z[i] = float(samples.z[i] - origin.z());
  }
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::vector<std::pair<std::size_t, std::size_t>> leaves;
  const float* xyz[3] = {x.data(), y.data(), z.data()};
  if (n > 0) split(order, 0, n, xyz, leaves);
  slot_.resize(n);
  for (const auto& [first, last] : leaves) {
    Tile t{std::uint32_t(xs_.size()), Vec3::Constant(std::numeric_limits<double>::infinity()),
           Vec3::Constant(-std::numeric_limits<double>::infinity()), 0};
    for (std::size_t k = 0; k < kTile; ++k) {
      const std::uint32_t i = order[first + k < last ? first + k : first];  // padding: the first sample again
      if (first + k < last) slot_[i] = std::uint32_t(xs_.size());
      xs_.push_back(x[i]), ys_.push_back(y[i]), zs_.push_back(z[i]);
      t.lo = t.lo.cwiseMin(Vec3(x[i], y[i], z[i])), t.hi = t.hi.cwiseMax(Vec3(x[i], y[i], z[i]));
    }
    t.margin = 1e-5 * std::max(t.lo.cwiseAbs().maxCoeff(), t.hi.cwiseAbs().maxCoeff());
    tiles_.push_back(t);
  }
}

void TiledSamples::nearest_squared(const FlowSegment* first, const FlowSegment* last, float* m) const {
  static thread_local Bores s;
  const std::size_t nb = std::size_t(last - first);
  s.segment.resize(nb);
  s.axis.resize(nb);
  for (int k = 0; k < 3; ++k) s.lo[k].resize(nb), s.hi[k].resize(nb);
  s.margin.resize(nb);
  s.gap2.resize(nb);
  for (std::size_t b = 0; b < nb; ++b) {
    auto& f = s.segment[b];
    const Vec3 a = first[b].start - origin_, d = first[b].end - first[b].start;
    for (std::size_t k = 0; k < 3; ++k) f[k] = float(a[int(k)]), f[k + 3] = float(d[int(k)]);
    const float dd = f[3] * f[3] + f[4] * f[4] + f[5] * f[5];
    f[6] = dd > 0 ? 1 / dd : 0;
    s.axis[b] = -1;
    for (int k = 0; k < 3; ++k)
      if (f[3 + k] != 0 && f[3 + (k + 1) % 3] == 0 && f[3 + (k + 2) % 3] == 0) s.axis[b] = k;
    double scale = 0;
    for (std::size_t k = 0; k < 3; ++k) {
      const double p = f[k], q = double(f[k]) + double(f[k + 3]);
      s.lo[k][b] = std::min(p, q), s.hi[k][b] = std::max(p, q);
      scale = std::max({scale, std::abs(p), std::abs(q), std::abs(double(f[k + 3]))});
    }
    s.margin[b] = 1e-5 * (2 * scale + 1);
  }
  score_tiles(tiles_.data(), tiles_.size(), xs_.data(), ys_.data(), zs_.data(), s, m);
}

}  // namespace mtcs::eval
