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

class ThermalStage final : public Stage {
 public:
  ThermalStage(const mold::Scene& scene, SurfaceSamples samples)
      : samples_(std::move(samples)), total_(samples_.total_weight()),
        target_(scene.spec().objectives.target_wall_distance),
        no_bore_(scene.block_bounds().size().norm()) {
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
    std::vector<double> best(n, no_bore_), diameter(n, 0), near2(n);
    const double* xs = samples_.x.data();
    const double* ys = samples_.y.data();
    const double* zs = samples_.z.data();
    std::size_t b = 0;
    while (b < layout.bores.size()) {
      // Bores of one circuit share a radius: minimise squared distances, one root per sample.
      const int circuit = layout.bores[b].circuit;
      const double r = layout.bores[b].diameter / 2;
      std::fill(near2.begin(), near2.end(), std::numeric_limits<double>::infinity());
      for (; b < layout.bores.size() && layout.bores[b].circuit == circuit; ++b) {
        const Vec3 a = layout.bores[b].flow_start, d = layout.bores[b].flow_end - a;
        const double inv = d.squaredNorm() > 0 ? 1 / d.squaredNorm() : 0;
        const double ax = a.x(), ay = a.y(), az = a.z(), dx = d.x(), dy = d.y(), dz = d.z();
        double* m = near2.data();
        for (std::size_t i = 0; i < n; ++i) {
          const double px = xs[i] - ax, py = ys[i] - ay, pz = zs[i] - az;
          double t = (px * dx + py * dy + pz * dz) * inv;
          t = t < 0 ? 0 : (t > 1 ? 1 : t);
          const double qx = px - t * dx, qy = py - t * dy, qz = pz - t * dz;
          const double d2 = qx * qx + qy * qy + qz * qz;
          m[i] = d2 < m[i] ? d2 : m[i];
        }
      }
      for (std::size_t i = 0; i < n; ++i) {
        const double e = std::sqrt(near2[i]) - r;
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
  int uniformity_slot_ = -1, worst_slot_ = -1;
};

}  // namespace

std::unique_ptr<Stage> make_thermal_stage(const mold::Scene& scene, SurfaceSamples samples) {
  return std::make_unique<ThermalStage>(scene, std::move(samples));
}

}  // namespace mtcs::eval
