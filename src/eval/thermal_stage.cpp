// Thermal proxy objectives (tier 0, shared/notes/mtcs_literature.md 7.4): for each cavity-surface
// sample the effective wall distance to the nearest flow bore, e_i = min_b |s_i - axis_b| - r_b.
//   uniformity    = sqrt(sum w_i (e_i - e*_i)^2 / W), e* = target_wall_distance at the nearest
//                   bore's diameter (default 2 D);
//   worst_covered = max_i e_i, the sample farthest from cooling.

#include <algorithm>
#include <cmath>
#include <cstring>
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

// e[i] = sqrt(m[i]) - r: a circuit's squared distances to effective wall distances. The root in
// single precision, as m is: its rounding (6e-8 relative) is m's own, at a fraction of the cost of
// a double root (vsqrtpd's throughput was ~9 % of a plate run; experiments/evaluate/es_run.md).
__attribute__((target_clones("avx2", "default"))) void wall_distances(const float* __restrict m, double r,
                                                                      double* __restrict e, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) e[i] = double(std::sqrt(m[i])) - r;
}

// Per slot, the nearest circuit's e (from `n` circuits' rows e[c], targets t[c]; none and t0
// without one): the largest e, and the weighted sum of (e - target)^2. Blocks of kBlock slots
// stay in registers and L1 across the circuits; the sum runs in eight fixed lanes (the same
// order on every machine and clone, so one result), not the one chain a sum in samples' order
// would wait on.
constexpr std::size_t kBlock = 32;
static_assert(TiledSamples::kTile % kBlock == 0);
struct Nearest {
  double largest, weighted_sum;
};
// GCC 12 takes the default clone's 256-bit stores, done as two halves, for reads of an
// uninitialised `target`: a false warning.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
__attribute__((target_clones("avx2", "default"))) Nearest nearest_circuits(const double* const* e, const double* t,
                                                                           std::size_t n, double none, double t0,
                                                                           const double* __restrict weight,
                                                                           std::size_t slots) {
  // Four doubles a vector; a block's 32 slots are 8 vectors, vector j holding slots 4j..4j+3,
  // so that lane l of `sum[j % 2]` sums the slots k with k % 8 = 4 (j % 2) + l.
  using D4 = double __attribute__((vector_size(32)));
  constexpr int kVectors = int(kBlock / 4);
  const double inf = std::numeric_limits<double>::infinity();
  D4 sum[2] = {{0, 0, 0, 0}, {0, 0, 0, 0}}, top[2] = {{-inf, -inf, -inf, -inf}, {-inf, -inf, -inf, -inf}};
  const D4 none4 = {none, none, none, none}, t04 = {t0, t0, t0, t0};
  for (std::size_t k0 = 0; k0 < slots; k0 += kBlock) {  // slots: a whole number of tiles of 32
    D4 best[kVectors], target[kVectors];
    for (int j = 0; j < kVectors; ++j) {
      best[j] = none4;
      target[j] = t04;
    }
    for (std::size_t c = 0; c < n; ++c) {
      const D4 tc = {t[c], t[c], t[c], t[c]};
      for (int j = 0; j < kVectors; ++j) {
        D4 ec;
        std::memcpy(&ec, e[c] + k0 + 4 * std::size_t(j), sizeof ec);
        const auto nearer = ec < best[j];
        best[j] = nearer ? ec : best[j];
        target[j] = nearer ? tc : target[j];
      }
    }
    for (int j = 0; j < kVectors; ++j) {
      D4 w;
      std::memcpy(&w, weight + k0 + 4 * std::size_t(j), sizeof w);
      const D4 dev = best[j] - target[j];
      sum[j % 2] += w * dev * dev;
      top[j % 2] = best[j] > top[j % 2] ? best[j] : top[j % 2];
    }
  }
  double total = 0, largest = top[0][0];
  for (int h = 0; h < 2; ++h)
    for (int l = 0; l < 4; ++l) total += sum[h][l], largest = top[h][l] > largest ? top[h][l] : largest;
  return {largest, total};
}
#pragma GCC diagnostic pop

class ThermalStage final : public Stage {
 public:
  ThermalStage(const mold::Scene& scene, SurfaceSamples samples)
      : samples_(std::move(samples)), total_(samples_.total_weight()),
        target_(scene.spec().objectives.target_wall_distance),
        no_bore_(scene.block_bounds().size().norm()), tiles_(samples_, scene.block_bounds().min),
        slot_weight_(tiles_.slots(), 0.0) {
    for (std::size_t i = 0; i < samples_.size(); ++i) slot_weight_[tiles_.slot(i)] = samples_.weight[i];
    const auto& use = scene.spec().objectives.use;
    for (std::size_t k = 0; k < use.size(); ++k) {
      if (use[k] == mold::Objective::Uniformity) uniformity_slot_ = int(k);
      if (use[k] == mold::Objective::WorstCovered) worst_slot_ = int(k);
    }
  }

  std::string name() const override { return "thermal"; }

  void run(const mold::Layout& layout, Evaluation& out) const override {
    // Each circuit's e per slot of the tiled samples (cached by its geometry), then per slot the
    // nearest circuit's e and the target at its diameter. Per thread: no allocation.
    static thread_local std::vector<const double*> rows;
    static thread_local std::vector<double> targets, copies;
    rows.clear(), targets.clear();
    std::size_t circuits = 0;
    for (std::size_t b = 0; b < layout.bores.size(); ++b) circuits += b == 0 || layout.bores[b].circuit != layout.bores[b - 1].circuit;
    // More circuits than the ring keeps for one layout (no mold has them): each row copied.
    const bool copy = circuits > kPerLayout;
    if (copy) copies.resize(circuits * tiles_.slots());
    std::size_t b = 0;
    while (b < layout.bores.size()) {
      const std::size_t first = b;
      const int circuit = layout.bores[b].circuit;
      while (b < layout.bores.size() && layout.bores[b].circuit == circuit) ++b;
      const double r = layout.bores[first].diameter / 2;
      targets.push_back(target_.at(2 * r));
      const double* e = circuit_distances(layout, first, b, r);
      if (copy) e = std::copy_n(e, tiles_.slots(), copies.data() + rows.size() * tiles_.slots()) - tiles_.slots();
      rows.push_back(e);
    }
    const Nearest n = nearest_circuits(rows.data(), targets.data(), rows.size(), no_bore_, target_.at(0),
                                       slot_weight_.data(), tiles_.slots());
    if (uniformity_slot_ >= 0) out.objectives[std::size_t(uniformity_slot_)] = std::sqrt(n.weighted_sum / total_);
    // A padded slot repeats a sample (weight 0 in the sum): the maximum is the samples'.
    if (worst_slot_ >= 0) out.objectives[std::size_t(worst_slot_)] = n.largest;
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
    const std::size_t slots = tiles_.slots();
    const auto compute = [&] {
      // Recomputed rather than cached per bore: a bore's column costs ~2 us to compute and about
      // as much to fetch from memory once the cache outgrows the processor's (experiments/evaluate).
      static thread_local std::vector<FlowSegment> segments;
      static thread_local std::vector<float> near2;
      segments.clear();
      for (std::size_t b = first; b < last; ++b) segments.push_back({layout.bores[b].flow_start, layout.bores[b].flow_end});
      near2.resize(slots);
      tiles_.nearest_squared(segments.data(), segments.data() + segments.size(), near2.data());
      double* e = next_row();
      wall_distances(near2.data(), r, e, slots);
      return static_cast<const double*>(e);
    };
    // A row found in the cache's old generation is copied to a fresh one: rows are recycled in
    // the order they were written.
    const auto revive = [&](const double*&& row) {
      return static_cast<const double*>(std::copy_n(row, slots, next_row()) - slots);
    };
    return circuits_.get(key, compute, revive);
  }

  // The next row of this thread's ring. A cache entry's row was written at most 2 kCircuits rows
  // ago (an entry lives two generations, a revived one gets a new row), and a layout writes at
  // most kPerLayout rows, so the rows a layout has looked up stay whole until its end.
  double* next_row() const {
    const std::size_t slots = tiles_.slots();
    Ring& ring = rows_.local();
    if (ring.rows.empty()) ring.rows.resize(kRing * slots);
    double* e = ring.rows.data() + ring.next * slots;
    ring.next = (ring.next + 1) % kRing;
    return e;
  }

  SurfaceSamples samples_;
  double total_;
  mold::Length target_;
  double no_bore_;      // e_i without any bore: the block's diagonal
  TiledSamples tiles_;  // relative to the block's corner
  std::vector<double> slot_weight_;  // the samples' weights by slot (padding: 0)
  int uniformity_slot_ = -1, worst_slot_ = -1;
  // Per thread, by exact geometry: a child's unchanged circuits are not recomputed. The values
  // point into a ring of rows allocated once per thread (a column is ~18 kB on the plate: no
  // malloc and free of that size per new circuit, nor per start-over of the cache).
  static constexpr std::size_t kCircuits = 128, kPerLayout = 64, kRing = 2 * kCircuits + kPerLayout;
  ExactCache<std::vector<double>, const double*> circuits_{kCircuits};
  struct Ring {
    std::vector<double> rows;
    std::size_t next = 0;
  };
  mutable tbb::enumerable_thread_specific<Ring> rows_;
};

}  // namespace

std::unique_ptr<Stage> make_thermal_stage(const mold::Scene& scene, SurfaceSamples samples) {
  return std::make_unique<ThermalStage>(scene, std::move(samples));
}

}  // namespace mtcs::eval
