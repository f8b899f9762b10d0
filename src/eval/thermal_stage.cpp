// Thermal proxy objectives (tier 0, shared/notes/mtcs_literature.md 7.4): for each cavity-surface
// sample the effective wall distance to the nearest flow bore, e_i = min_b |s_i - axis_b| - r_b.
//   uniformity    = sqrt(sum w_i (e_i - e*_i)^2 / W), e* = target_wall_distance at the nearest
//                   bore's diameter (default 2 D);
//   worst_covered = max_i e_i, the sample farthest from cooling.

#include <algorithm>
#include <cmath>

#include "mtcs/mold/decoder.h"
#include "stages.h"

namespace mtcs::eval {
namespace {

using geometry::Vec3;

// m[i] = min(m[i], |p_i - segment|^2) over n samples, in single precision relative to the
// block's corner (coordinates below ~1e3 mm: errors ~1e-4 mm, far below what the proxy
// resolves). Compiled for AVX2 and for the baseline, chosen at run time.
__attribute__((target_clones("avx2", "default"))) void nearer_squared(const float* xs, const float* ys,
                                                                      const float* zs, std::size_t n,
                                                                      const float a[3], const float d[3],
                                                                      float inv, float* m) {
  const float ax = a[0], ay = a[1], az = a[2], dx = d[0], dy = d[1], dz = d[2];
  for (std::size_t i = 0; i < n; ++i) {
    const float px = xs[i] - ax, py = ys[i] - ay, pz = zs[i] - az;
    float t = (px * dx + py * dy + pz * dz) * inv;
    t = t < 0.f ? 0.f : (t > 1.f ? 1.f : t);
    const float qx = px - t * dx, qy = py - t * dy, qz = pz - t * dz;
    const float d2 = qx * qx + qy * qy + qz * qz;
    m[i] = d2 < m[i] ? d2 : m[i];
  }
}

class ThermalStage final : public Stage {
 public:
  ThermalStage(const mold::Scene& scene, SurfaceSamples samples)
      : samples_(std::move(samples)), total_(samples_.total_weight()),
        target_(scene.spec().objectives.target_wall_distance),
        no_bore_(scene.block_bounds().size().norm()), origin_(scene.block_bounds().min) {
    for (std::size_t i = 0; i < samples_.size(); ++i) {
      xs_.push_back(float(samples_.x[i] - origin_.x()));
      ys_.push_back(float(samples_.y[i] - origin_.y()));
      zs_.push_back(float(samples_.z[i] - origin_.z()));
    }
    const auto& use = scene.spec().objectives.use;
    for (std::size_t k = 0; k < use.size(); ++k) {
      if (use[k] == mold::Objective::Uniformity) uniformity_slot_ = int(k);
      if (use[k] == mold::Objective::WorstCovered) worst_slot_ = int(k);
    }
  }

  std::string name() const override { return "thermal"; }

  void run(const mold::Layout& layout, Evaluation& out) const override {
    const std::size_t n = samples_.size();
    // Per sample: the nearest flow bore's effective distance and its diameter.
    std::vector<double> best(n, no_bore_), diameter(n, 0);
    std::vector<float> near2(n);
    std::size_t b = 0;
    while (b < layout.bores.size()) {
      // Bores of one circuit share a radius: minimise squared distances, one root per sample.
      const int circuit = layout.bores[b].circuit;
      const double r = layout.bores[b].diameter / 2;
      std::fill(near2.begin(), near2.end(), std::numeric_limits<float>::infinity());
      for (; b < layout.bores.size() && layout.bores[b].circuit == circuit; ++b) {
        const Vec3 a = layout.bores[b].flow_start - origin_, d = layout.bores[b].flow_end - layout.bores[b].flow_start;
        const float fa[3] = {float(a.x()), float(a.y()), float(a.z())};
        const float fd[3] = {float(d.x()), float(d.y()), float(d.z())};
        const float dd = fd[0] * fd[0] + fd[1] * fd[1] + fd[2] * fd[2];
        nearer_squared(xs_.data(), ys_.data(), zs_.data(), n, fa, fd, dd > 0 ? 1 / dd : 0, near2.data());
      }
      for (std::size_t i = 0; i < n; ++i) {
        const double e = std::sqrt(double(near2[i])) - r;
        if (e < best[i]) best[i] = e, diameter[i] = 2 * r;
      }
    }
    if (uniformity_slot_ >= 0) {
      double sum = 0;
      for (std::size_t i = 0; i < n; ++i) {
        const double dev = best[i] - target_.at(diameter[i] > 0 ? diameter[i] : 0);
        sum += samples_.weight[i] * dev * dev;
      }
      out.objectives[std::size_t(uniformity_slot_)] = std::sqrt(sum / total_);
    }
    if (worst_slot_ >= 0) out.objectives[std::size_t(worst_slot_)] = *std::max_element(best.begin(), best.end());
  }

 private:
  SurfaceSamples samples_;
  double total_;
  mold::Length target_;
  double no_bore_;  // e_i without any bore: the block's diagonal
  Vec3 origin_;     // the block's corner: single-precision coordinates are relative to it
  std::vector<float> xs_, ys_, zs_;
  int uniformity_slot_ = -1, worst_slot_ = -1;
};

}  // namespace

std::unique_ptr<Stage> make_thermal_stage(const mold::Scene& scene, SurfaceSamples samples) {
  return std::make_unique<ThermalStage>(scene, std::move(samples));
}

}  // namespace mtcs::eval
