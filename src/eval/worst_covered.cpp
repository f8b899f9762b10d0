#include "mtcs/eval/worst_covered.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "mtcs/geometry/segment_distance.h"
#include "exact_cache.h"
#include "tiled_samples.h"

namespace mtcs::eval {

using geometry::Vec3;

struct WorstCoveredSearch::Tiles {
  TiledSamples tiled;
  // Per thread, by the bores' exact geometry: the reach move asks about a parent once per child
  // it makes (tests/eval/worst_covered_test.cpp).
  ExactCache<std::vector<double>, WorstSample> found{64};
};

namespace {

SurfaceSamples as_surface_samples(const std::vector<Vec3>& points) {
  SurfaceSamples s;
  for (const Vec3& p : points) s.x.push_back(p.x()), s.y.push_back(p.y()), s.z.push_back(p.z()), s.weight.push_back(1);
  return s;
}

double exact_wall_distance(const mold::Layout& layout, const Vec3& p) {
  double e = std::numeric_limits<double>::infinity();
  for (const mold::Bore& b : layout.bores)
    e = std::min(e, geometry::point_segment_distance(p, {b.flow_start, b.flow_end}) - b.diameter / 2);
  return e;
}

}  // namespace

WorstCoveredSearch::WorstCoveredSearch(std::vector<Vec3> samples, const Vec3& origin)
    : samples_(std::move(samples)), origin_(origin),
      tiles_(std::make_unique<Tiles>(Tiles{TiledSamples(as_surface_samples(samples_), origin)})) {
  for (const Vec3& p : samples_) sample_scale_ = std::max(sample_scale_, (p - origin_).cwiseAbs().maxCoeff());
}

WorstCoveredSearch::~WorstCoveredSearch() = default;
WorstCoveredSearch::WorstCoveredSearch(WorstCoveredSearch&&) noexcept = default;
WorstCoveredSearch& WorstCoveredSearch::operator=(WorstCoveredSearch&&) noexcept = default;

WorstSample WorstCoveredSearch::find(const mold::Layout& layout) const {
  if (samples_.empty()) return {};
  if (layout.bores.empty()) return {samples_.front(), std::numeric_limits<double>::infinity(), true};
  static thread_local std::vector<double> key;  // per thread: a lookup that hits allocates nothing
  key.clear();
  for (const mold::Bore& b : layout.bores)
    key.insert(key.end(), {b.flow_start.x(), b.flow_start.y(), b.flow_start.z(), b.flow_end.x(), b.flow_end.y(),
                           b.flow_end.z(), b.diameter});
  return tiles_->found.get(key, [&] { return search(layout); });
}

WorstSample WorstCoveredSearch::search(const mold::Layout& layout) const {
  const TiledSamples& tiles = tiles_->tiled;
  const std::size_t slots = tiles.slots();
  // Per thread: no allocation per search.
  static thread_local std::vector<double> screen;
  static thread_local std::vector<float> near2;
  static thread_local std::vector<FlowSegment> segments;
  static thread_local std::vector<double> radii;
  screen.assign(slots, std::numeric_limits<double>::infinity());
  near2.resize(slots);
  // The screen: per radius, the nearest bore's squared distance in single precision.
  radii.clear();
  double scale = sample_scale_;
  for (const mold::Bore& b : layout.bores) {
    if (std::find(radii.begin(), radii.end(), b.diameter / 2) == radii.end()) radii.push_back(b.diameter / 2);
    scale = std::max({scale, (b.flow_start - origin_).cwiseAbs().maxCoeff(), (b.flow_end - origin_).cwiseAbs().maxCoeff(),
                      (b.flow_end - b.flow_start).cwiseAbs().maxCoeff()});
  }
  for (const double r : radii) {
    segments.clear();
    for (const mold::Bore& b : layout.bores)
      if (b.diameter / 2 == r) segments.push_back({b.flow_start, b.flow_end});
    tiles.nearest_squared(segments.data(), segments.data() + segments.size(), near2.data());
    for (std::size_t k = 0; k < slots; ++k) screen[k] = std::min(screen[k], std::sqrt(double(near2[k])) - r);
  }
  // A screened distance is within `bound` of the exact one: single-precision coordinates round by
  // ~6e-8 of `scale`, the distance by a few times that; 1e-5 is TiledSamples' margin, 50 times
  // over. The exact maximum is screened at least (screened maximum - 2 bound).
  const double bound = 1e-5 * (2 * scale + 1);
  double top = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < samples_.size(); ++i) top = std::max(top, screen[tiles.slot(i)]);
  WorstSample worst;
  for (std::size_t i = 0; i < samples_.size(); ++i) {
    if (!(screen[tiles.slot(i)] >= top - 2 * bound)) continue;
    const double e = exact_wall_distance(layout, samples_[i]);
    if (!worst.any || e > worst.wall_distance) worst = {samples_[i], e, true};
  }
  return worst;
}

}  // namespace mtcs::eval
