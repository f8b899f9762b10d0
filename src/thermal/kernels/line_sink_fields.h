#pragma once
// The pieces of the line-sink tiers that know geometry but not the system: the block's image
// lattice, and the fields of all elements of one channel at a point (shared distances).

#include <array>
#include <cmath>
#include <span>
#include <vector>

#include "mtcs/thermal/model.h"
#include "thermal/kernels/segment_potential.h"

namespace mtcs::thermal {

// One image of the block's reflection group: x -> mult .* x + offset, weighted by sign (-1 for
// each reflection across an isothermal face). A source's image field at s equals the source's
// field at the image of s, since the group is closed under inversion.
struct Image {
  Vec3 mult = Vec3::Ones();
  Vec3 offset = Vec3::Zero();
  double sign = 1;
};
// All images reached by at most `levels` reflections across the six faces (identity first).
// face_sign: +1 (adiabatic or convective) or -1 (isothermal) per BlockFace.
std::vector<Image> block_images(const Box& block, const std::array<double, 6>& face_sign,
                                int levels);

// The far images of the block, each seen as a point charge and dipole at the image of its
// centre c: (sum sigma / d, sum sigma L_g (s - g(c)) / d^3), d = |s - g(c)|. Dotted with the
// charge and first moment (about c) of everything in the block, then divided by 4 pi k, it is
// the far lattice's field at s.
inline Eigen::Vector4d far_lattice_kernel(std::span<const Image> far, const Vec3& center, const Vec3& s) {
  Eigen::Vector4d k = Eigen::Vector4d::Zero();
  for (const Image& g : far) {
    const Vec3 d = s - (g.mult.cwiseProduct(center) + g.offset);
    const double r2 = d.squaredNorm();
    const double inv = 1 / std::sqrt(r2);
    k[0] += g.sign * inv;
    k.tail<3>() += (g.sign * inv / r2) * g.mult.cwiseProduct(d);
  }
  return k;
}

struct WeightedPoint {
  Vec3 point;
  double weight;
};
// Appends the images of s; images that land on s or on each other within tol (a point on a
// face) are merged into one point of summed weight.
void append_image_points(std::span<const Image> images, const Vec3& s, double tol,
                         std::vector<WeightedPoint>& out);

// A channel's axis cut into equal elements, with a transverse frame (n1, n2) for the dipoles.
struct ChannelAxis {
  Vec3 p0, u, n1, n2;
  double length = 0, element_length = 0, radius = 0;
  int elements = 1;
};
ChannelAxis channel_axis(const Channel& channel, int elements);

// At s, for each element e: phi[e] = the line source's potential (notes 4.4), and when dip1 is
// given, dip1[e], dip2[e] = the potential of a unit transverse line dipole along n1, n2.
// Nodes are shared by neighbouring elements: elements + 1 square roots per point.
void element_fields(const ChannelAxis& axis, const Vec3& s, double* phi, double* dip1,
                    double* dip2);

// element_fields for many points at once in single precision, vectorised (AVX2 when the CPU
// has it): points as x, y, z arrays relative to `origin`, out[(e * kinds + k) * n + i] with
// k = 0 the sink's phi and k = 1, 2 the dipoles (kinds 3). Relative error ~1e-6.
void element_fields_float(const ChannelAxis& axis, const Vec3& origin, int kinds, const float* x,
                          const float* y, const float* z, std::size_t n, float* out);
// Chunks of `chunk` consecutive targets of a slot layout, each slot's chunk with the bounding box
// of its points (box + 6 * (slot * chunks + c): min x, y, z, max x, y, z). A chunk whose box
// lies at least h / ratio from every element's centre (h: the half length) takes the elements'
// multipole expansions instead of the closed forms: relative error below ratio^8 / 9 for the
// sink and 5 ratio^8 for the dipoles, over 1 - ratio^2 (element_fields_float.cpp).
struct FarChunks {
  const float* box = nullptr;
  std::size_t chunk = 0;
  float ratio = 0;
};
// The same over the slot layout of many targets (PointSet::make_slots): point j of target t at
// j * targets + t with weight w there; out[c * targets + t] += the weighted sum over the slots.
// With `far`, the far chunks by the expansions.
void element_fields_float_slots(const ChannelAxis& axis, const Vec3& origin, int kinds, const float* x,
                                const float* y, const float* z, const float* w, std::size_t targets,
                                int slots, float* out, const FarChunks* far = nullptr);

// T[s] += sum over c of x[c] * double(cols[c * n + s]), s < n: a channel's float columns at the
// samples weighted by its strengths (AVX2 when the CPU has it; chunks of samples kept in cache).
void accumulate_float_columns(const float* cols, std::size_t n, int ncols, const double* x, double* T);

// The potential of a uniform unit source on a triangle, summed over the images at s.
double triangle_image_potential(std::span<const Image> images, const TriangleSource& triangle, const Vec3& s);

}  // namespace mtcs::thermal
