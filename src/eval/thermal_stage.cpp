// Thermal proxy objectives (tier 0, shared/notes/mtcs_literature.md 7.4): for each cavity-surface
// sample the effective wall distance to the nearest flow bore, e_i = min_b |s_i - axis_b| - r_b.
//   uniformity    = sqrt(sum w_i (e_i - e*_i)^2 / W), e* = target_wall_distance at the nearest
//                   bore's diameter (default 2 D);
//   worst_covered = max_i e_i, the sample farthest from cooling.

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include <tbb/enumerable_thread_specific.h>

#include "mtcs/mold/decoder.h"
#include "exact_cache.h"
#include "stages.h"
#include "tiled_samples.h"

namespace mtcs::eval {
namespace {

using geometry::Vec3;

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

// take_nearer for a layout's first circuit, against no bore (e_i = none, target t0): the arrays
// need no filling first, nor reading back.
__attribute__((target_clones("avx2", "default"))) void take_first(const double* __restrict e, double t, double none,
                                                                  double t0, double* __restrict best,
                                                                  double* __restrict target, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) {
    const bool nearer = e[i] < none;
    best[i] = nearer ? e[i] : none;
    target[i] = nearer ? t : t0;
  }
}

// The largest of x[0..n), n > 0, in four independent chains (one chain waits on every max). The
// value is std::max_element's: the e_i are neither NaN nor -0 (roots minus radii), so max is exact
// and does not depend on the order.
double largest(const double* x, std::size_t n) {
  if (n == 0) return -std::numeric_limits<double>::infinity();
  double m[4] = {x[0], x[0], x[0], x[0]};
  std::size_t i = 0;
  for (; i + 4 <= n; i += 4)
    for (int k = 0; k < 4; ++k) m[k] = x[i + std::size_t(k)] > m[k] ? x[i + std::size_t(k)] : m[k];
  for (; i < n; ++i) m[0] = x[i] > m[0] ? x[i] : m[0];
  return std::max(std::max(m[0], m[1]), std::max(m[2], m[3]));
}

class ThermalStage final : public Stage {
 public:
  ThermalStage(const mold::Scene& scene, SurfaceSamples samples)
      : samples_(std::move(samples)), total_(samples_.total_weight()),
        target_(scene.spec().objectives.target_wall_distance),
        no_bore_(scene.block_bounds().size().norm()), tiles_(samples_, scene.block_bounds().min) {
    const auto& use = scene.spec().objectives.use;
    for (std::size_t k = 0; k < use.size(); ++k) {
      if (use[k] == mold::Objective::Uniformity) uniformity_slot_ = int(k);
      if (use[k] == mold::Objective::WorstCovered) worst_slot_ = int(k);
    }
  }

  std::string name() const override { return "thermal"; }

  void run(const mold::Layout& layout, Evaluation& out) const override {
    // Per slot of the tiled samples: the nearest flow bore's effective distance and the target
    // at its diameter (branch-free, so that the loop over the slots vectorises). Per thread: no
    // allocation per evaluation.
    const std::size_t slots = tiles_.slots();
    static thread_local std::vector<double> best, target;
    best.resize(slots);
    target.resize(slots);
    std::size_t b = 0;
    while (b < layout.bores.size()) {
      const std::size_t first = b;
      const int circuit = layout.bores[b].circuit;
      while (b < layout.bores.size() && layout.bores[b].circuit == circuit) ++b;
      const double r = layout.bores[first].diameter / 2, t = target_.at(2 * r);
      const double* e = circuit_distances(layout, first, b, r);
      if (first == 0)
        take_first(e, t, no_bore_, target_.at(0), best.data(), target.data(), slots);
      else
        take_nearer(e, t, best.data(), target.data(), slots);
    }
    if (layout.bores.empty()) {
      std::fill(best.begin(), best.end(), no_bore_);
      std::fill(target.begin(), target.end(), target_.at(0));
    }
    // In the samples' order (a padded slot repeats a sample: the maximum is the samples').
    if (uniformity_slot_ >= 0) {
      double sum = 0;
      for (std::size_t i = 0; i < samples_.size(); ++i) {
        const std::size_t k = tiles_.slot(i);
        const double dev = best[k] - target[k];
        sum += samples_.weight[i] * dev * dev;
      }
      out.objectives[std::size_t(uniformity_slot_)] = std::sqrt(sum / total_);
    }
    if (worst_slot_ >= 0) out.objectives[std::size_t(worst_slot_)] = largest(best.data(), slots);
  }

 private:
  // e_i to the nearest bore of one circuit (bores [first, last) of the layout, radius r), per
  // slot. Bores of one circuit share a radius: squared distances are minimised, one root per sample.
  const double* circuit_distances(const mold::Layout& layout, std::size_t first, std::size_t last, double r) const {
    static thread_local std::vector<double> key;  // per thread: a lookup that hits allocates nothing
    key.assign(1, r);
    for (std::size_t b = first; b < last; ++b) {
      const auto& bore = layout.bores[b];
      key.insert(key.end(), {bore.flow_start.x(), bore.flow_start.y(), bore.flow_start.z(), bore.flow_end.x(),
                             bore.flow_end.y(), bore.flow_end.z()});
    }
    return circuits_.get(key, [&] {
      const std::size_t slots = tiles_.slots();
      // Recomputed rather than cached per bore: a bore's column costs ~2 us to compute and about
      // as much to fetch from memory once the cache outgrows the processor's (experiments/evaluate).
      static thread_local std::vector<FlowSegment> segments;
      static thread_local std::vector<float> near2;
      segments.clear();
      for (std::size_t b = first; b < last; ++b) segments.push_back({layout.bores[b].flow_start, layout.bores[b].flow_end});
      near2.resize(slots);
      tiles_.nearest_squared(segments.data(), segments.data() + segments.size(), near2.data());
      // The entry's own row of this thread's rows (a cache that starts over reuses them).
      std::vector<double>& rows = rows_.local();
      if (rows.empty()) rows.resize(kCircuits * slots);
      double* e = rows.data() + circuits_.entries() * slots;
      wall_distances(near2.data(), r, e, slots);
      return e;
    });
  }

  SurfaceSamples samples_;
  double total_;
  mold::Length target_;
  double no_bore_;      // e_i without any bore: the block's diagonal
  TiledSamples tiles_;  // relative to the block's corner
  int uniformity_slot_ = -1, worst_slot_ = -1;
  // Per thread, by exact geometry: a child's unchanged circuits are not recomputed. The values
  // point into rows allocated once per thread (a column is ~18 kB on the plate: no malloc and
  // free of that size per new circuit, nor per start-over of the cache).
  static constexpr std::size_t kCircuits = 256;
  ExactCache<std::vector<double>, const double*> circuits_{kCircuits};
  mutable tbb::enumerable_thread_specific<std::vector<double>> rows_;
};

}  // namespace

std::unique_ptr<Stage> make_thermal_stage(const mold::Scene& scene, SurfaceSamples samples) {
  return std::make_unique<ThermalStage>(scene, std::move(samples));
}

}  // namespace mtcs::eval
