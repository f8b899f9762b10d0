// Thermal proxy objectives (tier 0, shared/notes/mtcs_literature.md 7.4): for each cavity-surface
// sample the effective wall distance to the nearest flow bore, e_i = min_b |s_i - axis_b| - r_b.
//   uniformity    = sqrt(sum w_i (e_i - e*_i)^2 / W), e* = target_wall_distance at the nearest
//                   bore's diameter (default 2 D);
//   worst_covered = max_i e_i, the sample farthest from cooling.

#include <algorithm>
#include <cmath>
#include <memory>

#include "mtcs/mold/decoder.h"
#include "exact_cache.h"
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

// e[i] = sqrt(m[i]) - r: a circuit's squared distances to effective wall distances.
__attribute__((target_clones("avx2", "default"))) void wall_distances(const float* __restrict m, double r,
                                                                      double* __restrict e, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) e[i] = std::sqrt(double(m[i])) - r;
}

// Where circuit distances e are nearer than best: best = e, target = t.
__attribute__((target_clones("avx2", "default"))) void take_nearer(const double* __restrict e, double t,
                                                                   double* __restrict best,
                                                                   double* __restrict target, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) {
    const bool nearer = e[i] < best[i];
    best[i] = nearer ? e[i] : best[i];
    target[i] = nearer ? t : target[i];
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
    // Per sample: the nearest flow bore's effective distance and the target at its diameter
    // (branch-free, so that the loop over the samples vectorises).
    std::vector<double> best(n, no_bore_), target(n, target_.at(0));
    std::size_t b = 0;
    while (b < layout.bores.size()) {
      const std::size_t first = b;
      const int circuit = layout.bores[b].circuit;
      while (b < layout.bores.size() && layout.bores[b].circuit == circuit) ++b;
      const double r = layout.bores[first].diameter / 2, t = target_.at(2 * r);
      take_nearer(circuit_distances(layout, first, b, r).get(), t, best.data(), target.data(), n);
    }
    if (uniformity_slot_ >= 0) {
      double sum = 0;
      for (std::size_t i = 0; i < n; ++i) {
        const double dev = best[i] - target[i];
        sum += samples_.weight[i] * dev * dev;
      }
      out.objectives[std::size_t(uniformity_slot_)] = std::sqrt(sum / total_);
    }
    if (worst_slot_ >= 0) out.objectives[std::size_t(worst_slot_)] = *std::max_element(best.begin(), best.end());
  }

 private:
  // e_i to the nearest bore of one circuit (bores [first, last) of the layout, radius r). Bores
  // of one circuit share a radius: squared distances are minimised, one root per sample.
  const std::unique_ptr<double[]>& circuit_distances(const mold::Layout& layout, std::size_t first,
                                                     std::size_t last, double r) const {
    std::vector<double> key{r};
    for (std::size_t b = first; b < last; ++b) {
      const auto& bore = layout.bores[b];
      key.insert(key.end(), {bore.flow_start.x(), bore.flow_start.y(), bore.flow_start.z(), bore.flow_end.x(),
                             bore.flow_end.y(), bore.flow_end.z()});
    }
    return circuits_.get(key, [&] {
      const std::size_t n = samples_.size();
      // Recomputed rather than cached per bore: a bore's column costs ~2 us to compute and about
      // as much to fetch from memory once the cache outgrows the processor's (experiments/evaluate).
      std::vector<float> near2(n, std::numeric_limits<float>::infinity());
      for (std::size_t b = first; b < last; ++b) {
        const auto& bore = layout.bores[b];
        const Vec3 a = bore.flow_start - origin_, d = bore.flow_end - bore.flow_start;
        const float fa[3] = {float(a.x()), float(a.y()), float(a.z())};
        const float fd[3] = {float(d.x()), float(d.y()), float(d.z())};
        const float dd = fd[0] * fd[0] + fd[1] * fd[1] + fd[2] * fd[2];
        nearer_squared(xs_.data(), ys_.data(), zs_.data(), n, fa, fd, dd > 0 ? 1 / dd : 0, near2.data());
      }
      auto e = std::make_unique_for_overwrite<double[]>(n);
      wall_distances(near2.data(), r, e.get(), n);
      return e;
    });
  }

  SurfaceSamples samples_;
  double total_;
  mold::Length target_;
  double no_bore_;  // e_i without any bore: the block's diagonal
  Vec3 origin_;     // the block's corner: single-precision coordinates are relative to it
  std::vector<float> xs_, ys_, zs_;
  int uniformity_slot_ = -1, worst_slot_ = -1;
  // Per thread, by exact geometry: a child's unchanged circuits are not recomputed.
  ExactCache<std::vector<double>, std::unique_ptr<double[]>> circuits_{256};
};

}  // namespace

std::unique_ptr<Stage> make_thermal_stage(const mold::Scene& scene, SurfaceSamples samples) {
  return std::make_unique<ThermalStage>(scene, std::move(samples));
}

}  // namespace mtcs::eval
