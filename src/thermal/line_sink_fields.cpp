#include "line_sink_fields.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "segment_potential.h"

namespace mtcs::thermal {

namespace {

struct Image1d {
  double mult, offset, sign;
  int level;
  int last;  // the last face reflected across: 0 low, 1 high, -1 none
};

// Images along one axis: alternating reflections across the low and high face.
std::vector<Image1d> axis_images(double lo, double hi, double sign_lo, double sign_hi, int levels) {
  std::vector<Image1d> out{{1, 0, 1, 0, -1}};
  for (std::size_t i = 0; i < out.size(); ++i) {
    const Image1d g = out[i];
    if (g.level == levels) continue;
    if (g.last != 0) out.push_back({-g.mult, 2 * lo - g.offset, g.sign * sign_lo, g.level + 1, 0});
    if (g.last != 1) out.push_back({-g.mult, 2 * hi - g.offset, g.sign * sign_hi, g.level + 1, 1});
  }
  return out;
}

}  // namespace

std::vector<Image> block_images(const Box& block, const std::array<double, 6>& face_sign,
                                int levels) {
  std::array<std::vector<Image1d>, 3> per_axis;
  for (int a = 0; a < 3; ++a)
    per_axis[a] = axis_images(block.min[a], block.max[a], face_sign[2 * a], face_sign[2 * a + 1],
                              levels);
  std::vector<Image> out;
  // Ordered by total level so the identity comes first and nearer images before farther ones.
  for (int total = 0; total <= levels; ++total)
    for (const Image1d& x : per_axis[0])
      for (const Image1d& y : per_axis[1])
        for (const Image1d& z : per_axis[2]) {
          if (x.level + y.level + z.level != total) continue;
          out.push_back({Vec3(x.mult, y.mult, z.mult), Vec3(x.offset, y.offset, z.offset),
                         x.sign * y.sign * z.sign});
        }
  return out;
}

void append_image_points(std::span<const Image> images, const Vec3& s, double tol,
                         std::vector<WeightedPoint>& out) {
  const std::size_t first = out.size();
  for (const Image& g : images) {
    const Vec3 p = g.mult.cwiseProduct(s) + g.offset;
    bool merged = false;
    for (std::size_t i = first; i < out.size() && !merged; ++i)
      if ((out[i].point - p).cwiseAbs().maxCoeff() <= tol) {
        out[i].weight += g.sign;
        merged = true;
      }
    if (!merged) out.push_back({p, g.sign});
  }
  // An isothermal face through s cancels a pair exactly: drop the zero-weight points.
  std::size_t kept = first;
  for (std::size_t i = first; i < out.size(); ++i)
    if (out[i].weight != 0) out[kept++] = out[i];
  out.resize(kept);
}

ChannelAxis channel_axis(const Channel& channel, int elements) {
  ChannelAxis axis;
  const Vec3 d = channel.axis.p1 - channel.axis.p0;
  axis.p0 = channel.axis.p0;
  axis.length = d.norm();
  axis.u = d / axis.length;
  axis.n1 = axis.u.unitOrthogonal();
  axis.n2 = axis.u.cross(axis.n1);
  axis.elements = elements;
  axis.element_length = axis.length / elements;
  axis.radius = channel.radius;
  return axis;
}

void element_fields(const ChannelAxis& axis, const Vec3& s, double* phi, double* dip1,
                    double* dip2) {
  const Vec3 w = s - axis.p0;
  const double t0 = w.dot(axis.u);
  const Vec3 rho = w - t0 * axis.u;
  const double rho2 = rho.squaredNorm();
  const int m = axis.elements;
  // Per node i: its axial coordinate t, distance r, and the two cancellation-free pieces
  // r - t and r + t (notes 4.4), with t/r and 1/(r (r -+ t)) for the dipole.
  double t_prev = t0, r_prev = std::sqrt(rho2 + t0 * t0);
  for (int e = 0; e < m; ++e) {
    const double t_a = t_prev, r_a = r_prev;
    const double t_b = (e + 1 == m) ? t0 - axis.length : t0 - (e + 1) * axis.element_length;
    const double r_b = std::sqrt(rho2 + t_b * t_b);
    const double length = t_a - t_b;
    const double A = t_a > 0 ? rho2 / (r_a + t_a) : r_a - t_a;
    const double B = t_b < 0 ? rho2 / (r_b - t_b) : r_b + t_b;
    const double D = A + B;
    phi[e] = std::log((D + 2 * length) / D);
    if (dip1) {
      double factor;
      if (t_b >= 0) {
        factor = 1 / (r_b * (r_b + t_b)) - 1 / (r_a * (r_a + t_a));
      } else if (t_a <= 0) {
        factor = 1 / (r_a * (r_a - t_a)) - 1 / (r_b * (r_b - t_b));
      } else {
        factor = (t_a / r_a - t_b / r_b) / rho2;
      }
      dip1[e] = factor * rho.dot(axis.n1);
      dip2[e] = factor * rho.dot(axis.n2);
    }
    t_prev = t_b;
    r_prev = r_b;
  }
}

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

}  // namespace

namespace {

struct FloatAxis {
  float ax, ay, az, ux, uy, uz, n1x, n1y, n1z, n2x, n2y, n2z;
};

// One element's sink (and dipole) potentials at n points; no branch but selects.
template <bool Dipoles>
inline void element_float(const FloatAxis& g, float start, float len, const float* __restrict x,
                          const float* __restrict y, const float* __restrict z, std::size_t n,
                          float* __restrict phi, float* __restrict d1, float* __restrict d2) {
  for (std::size_t i = 0; i < n; ++i) {
    const float wx = x[i] - g.ax, wy = y[i] - g.ay, wz = z[i] - g.az;
    const float t0 = wx * g.ux + wy * g.uy + wz * g.uz;
    const float rx = wx - t0 * g.ux, ry = wy - t0 * g.uy, rz = wz - t0 * g.uz;
    const float rho2 = rx * rx + ry * ry + rz * rz;
    const float ta = t0 - start, tb = ta - len;
    const float ra = std::sqrt(rho2 + ta * ta), rb = std::sqrt(rho2 + tb * tb);
    // r + |t| and its reciprocal serve both kernels: r - t = rho^2/(r + t) when t > 0.
    const float pa = ra + std::abs(ta), pb = rb + std::abs(tb);
    const float ipa = 1 / pa, ipb = 1 / pb;
    const float A = ta > 0 ? rho2 * ipa : pa;
    const float B = tb < 0 ? rho2 * ipb : pb;
    const float D = A + B;
    phi[i] = log_float((D + 2 * len) / D);
    if constexpr (Dipoles) {
      // (ta/ra - tb/rb)/rho^2 in the cancellation-free forms of element_fields.
      const float ira = 1 / ra, irb = 1 / rb;
      const float ca = ipa * ira, cb = ipb * irb;
      const float across = (ta * ira - tb * irb) / rho2;
      const float factor = tb >= 0 ? cb - ca : (ta <= 0 ? ca - cb : across);
      d1[i] = factor * (rx * g.n1x + ry * g.n1y + rz * g.n1z);
      d2[i] = factor * (rx * g.n2x + ry * g.n2y + rz * g.n2z);
    }
  }
}

}  // namespace

__attribute__((target_clones("avx2", "default")))
void element_fields_float(const ChannelAxis& axis, const Vec3& origin, int kinds, const float* x,
                          const float* y, const float* z, std::size_t n, float* out) {
  const Vec3 a = axis.p0 - origin;
  const FloatAxis g{float(a.x()),       float(a.y()),       float(a.z()),
                    float(axis.u.x()),  float(axis.u.y()),  float(axis.u.z()),
                    float(axis.n1.x()), float(axis.n1.y()), float(axis.n1.z()),
                    float(axis.n2.x()), float(axis.n2.y()), float(axis.n2.z())};
  const int m = axis.elements;
  for (int e = 0; e < m; ++e) {
    const float start = float(e * axis.element_length);
    const float len = float((e + 1 == m ? axis.length : (e + 1) * axis.element_length) - e * axis.element_length);
    float* phi = out + std::size_t(e * kinds) * n;
    if (kinds == 3) element_float<true>(g, start, len, x, y, z, n, phi, phi + n, phi + 2 * n);
    else element_float<false>(g, start, len, x, y, z, n, phi, nullptr, nullptr);
  }
}

double triangle_image_potential(std::span<const Image> images, const Vec3& a, const Vec3& b,
                                const Vec3& c, const Vec3& s) {
  double sum = 0;
  for (const Image& g : images) sum += g.sign * triangle_potential(a, b, c, g.mult.cwiseProduct(s) + g.offset);
  return sum;
}

}  // namespace mtcs::thermal
