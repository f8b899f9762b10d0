#pragma once
// The tables the line-sink model precomputes: field points grouped by target, and fields on a
// grid over the block.

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <vector>

#include "line_sink_fields.h"

namespace mtcs::thermal {

// Field points expanded by their images, grouped by target (a sample, a wall point, a face),
// in double and, relative to the block's centre, in float for the vectorised kernel.
struct PointSet {
  std::vector<WeightedPoint> points;
  std::vector<float> x, y, z;
  std::vector<std::size_t> begin{0};
  std::size_t targets() const { return begin.size() - 1; }
  void add(std::span<const Image> images, const Vec3& p, double tol, double weight, const Vec3& centre) {
    const std::size_t first = points.size();
    append_image_points(images, p, tol, points);
    for (std::size_t i = first; i < points.size(); ++i) {
      points[i].weight *= weight;
      const Vec3 r = points[i].point - centre;
      x.push_back(float(r.x()));
      y.push_back(float(r.y()));
      z.push_back(float(r.z()));
    }
  }
  void close_target() { begin.push_back(points.size()); }

  // The slot layout of many targets (the samples): point j of target t at j * T + t, targets
  // with fewer images padded with weight 0, so that the sum over images runs contiguously.
  int slots = 0;
  std::vector<float> sx, sy, sz, sw;
  void make_slots() {
    const std::size_t T = targets();
    slots = 0;
    for (std::size_t t = 0; t < T; ++t) slots = std::max(slots, int(begin[t + 1] - begin[t]));
    const std::size_t n = std::size_t(slots) * T;
    sx.assign(n, 0.0f), sy.assign(n, 0.0f), sz.assign(n, 0.0f), sw.assign(n, 0.0f);
    for (std::size_t t = 0; t < T; ++t)
      for (int j = 0; j < slots; ++j) {
        const std::size_t i = std::min(begin[t] + j, begin[t + 1] - 1), k = j * T + t;
        sx[k] = x[i], sy[k] = y[i], sz[k] = z[i];
        sw[k] = begin[t] + j < begin[t + 1] ? float(points[i].weight) : 0.0f;
      }
  }

  // Per slot, the bounding boxes of chunks of `chunk` consecutive targets (FarChunks): where a
  // channel is far from a chunk, its fields there take the cheaper expansions.
  static constexpr std::size_t kChunk = 16;
  std::size_t chunk = kChunk;
  std::vector<float> chunk_box;
  void make_chunk_boxes(std::size_t size = kChunk) {
    chunk = size;
    const std::size_t T = targets(), chunks = (T + chunk - 1) / chunk;
    chunk_box.assign(6 * chunks * std::size_t(slots), 0.0f);
    for (int j = 0; j < slots; ++j)
      for (std::size_t c = 0; c < chunks; ++c) {
        float* b = &chunk_box[6 * (j * chunks + c)];
        for (std::size_t t = c * chunk; t < std::min(T, (c + 1) * chunk); ++t) {
          const std::size_t k = j * T + t;
          const float p[3] = {sx[k], sy[k], sz[k]};
          for (int a = 0; a < 3; ++a) {
            b[a] = t == c * chunk ? p[a] : std::min(b[a], p[a]);
            b[3 + a] = t == c * chunk ? p[a] : std::max(b[3 + a], p[a]);
          }
        }
      }
  }
};

// Layout-independent fields on a regular grid over the block, interpolated tricubically
// (4-point Lagrange per axis, the stencil kept inside the grid): the convective faces' losses,
// the heat input away from its triangles, the far lattice's kernel.
struct FieldGrid {
  Vec3 origin, step;
  std::array<int, 3> nodes{};
  int fields = 0;
  std::vector<double> values;  // per node (x fastest), `fields` values

  void interpolate(const Vec3& p, double* out) const {
    std::array<int, 3> i0;
    std::array<std::array<double, 4>, 3> w;
    for (int a = 0; a < 3; ++a) {
      const double u = (p[a] - origin[a]) / step[a];
      i0[a] = std::clamp(int(std::floor(u)) - 1, 0, nodes[a] - 4);
      const double t = u - i0[a];  // stencil nodes at 0, 1, 2, 3
      w[a] = {-(t - 1) * (t - 2) * (t - 3) / 6, t * (t - 2) * (t - 3) / 2,
              -t * (t - 1) * (t - 3) / 2, t * (t - 1) * (t - 2) / 6};
    }
    std::fill(out, out + fields, 0.0);
    for (int k = 0; k < 4; ++k)
      for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) {
          const double wt = w[0][i] * w[1][j] * w[2][k];
          const double* v = &values[((std::size_t(i0[2] + k) * nodes[1] + (i0[1] + j)) * nodes[0] + (i0[0] + i)) * fields];
          for (int f = 0; f < fields; ++f) out[f] += wt * v[f];
        }
  }
};

}  // namespace mtcs::thermal
