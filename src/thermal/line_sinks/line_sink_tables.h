#pragma once
// The tables the line-sink model precomputes: field points grouped by target, and fields on a
// grid over the block.

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <vector>

#include "thermal/kernels/line_sink_fields.h"

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

  void interpolate(const Vec3& p, double* out) const;
};

}  // namespace mtcs::thermal
