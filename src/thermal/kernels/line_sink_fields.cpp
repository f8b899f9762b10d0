#include "thermal/kernels/line_sink_fields.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "thermal/kernels/segment_potential.h"

namespace mtcs::thermal {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

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
  // Two images of s coincide only if s lies on a mirror plane of the group (a face or its
  // translates by the block's width): strictly between the faces, every image is its own point
  // and no merging is needed.
  Vec3 lo = Vec3::Constant(kInf), hi = Vec3::Constant(-kInf);
  for (const Image& g : images)
    for (int a = 0; a < 3; ++a)
      if (g.mult[a] < 0) lo[a] = std::min(lo[a], 0.5 * g.offset[a]), hi[a] = std::max(hi[a], 0.5 * g.offset[a]);
  bool inside = true;
  for (int a = 0; a < 3; ++a) inside = inside && (lo[a] == kInf || (s[a] > lo[a] + tol && s[a] < hi[a] - tol));
  if (inside) {
    for (const Image& g : images) out.push_back({g.mult.cwiseProduct(s) + g.offset, g.sign});
    return;
  }
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

double triangle_image_potential(std::span<const Image> images, const TriangleSource& triangle, const Vec3& s) {
  double sum = 0;
  for (const Image& g : images) sum += g.sign * triangle.potential(g.mult.cwiseProduct(s) + g.offset);
  return sum;
}

}  // namespace mtcs::thermal
