#include "mtcs/eval/part_sides.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mtcs::eval {

using geometry::Vec3;

namespace {

constexpr double kNone = std::numeric_limits<double>::infinity();

// The distance along the axis-parallel ray p + t d (t > 0) to the part, or kNone.
double part_ahead(const mold::Scene& scene, const Vec3& p, const Vec3& d) {
  const auto& cavity = *scene.spec().cavity;
  if (cavity.box) {
    const geometry::Box& b = *cavity.box;
    int axis = 0;
    d.cwiseAbs().maxCoeff(&axis);
    for (int k = 0; k < 3; ++k)
      if (k != axis && (p[k] < b.min[k] || p[k] > b.max[k])) return kNone;
    const double t = d[axis] > 0 ? b.min[axis] - p[axis] : p[axis] - b.max[axis];
    return t > 0 ? t : kNone;
  }
  const mesh::TriangleBvh* bvh = scene.cavity_bvh();
  const auto hit = bvh ? bvh->first_hit(p, d) : std::nullopt;
  return hit ? hit->t : kNone;
}

}  // namespace

std::vector<PartSide> part_sides(const mold::Scene& scene, const thermal::Samples& samples) {
  const auto& cavity = scene.spec().cavity;
  if (!cavity || !cavity->parting) return {};
  const mold::Parting& parting = *cavity->parting;
  const int axis = mold::axis_of(parting.core);
  const Vec3 to_core = mold::normal_of(parting.core);
  // A hair into the steel: well inside any wall, well off the face's own plane.
  const double hair = 1e-4 * (1 + cavity->bounds().size().norm());
  std::vector<PartSide> sides(samples.size());
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const bool has_normal = i < samples.normals.size() && samples.normals[i].squaredNorm() > 0.5;
    const Vec3 q = has_normal ? Vec3(samples.points[i] + hair * samples.normals[i]) : samples.points[i];
    const double above = (q[axis] - parting.at) * to_core[axis];  // > 0: on the core's side
    const PartSide own = above > 0 ? PartSide::Core : PartSide::Cavity;
    const PartSide other = above > 0 ? PartSide::Cavity : PartSide::Core;
    const Vec3 to_plane = above > 0 ? Vec3(-to_core) : to_core;
    // A sample with no normal (no steel side known) keeps the side of the plane it lies on.
    const bool reaches_in = has_normal && part_ahead(scene, q, -to_plane) < kNone &&
                            !(part_ahead(scene, q, to_plane) <= std::abs(above));
    sides[i] = reaches_in ? other : own;
  }
  return sides;
}

SideSummaries side_summaries(const std::vector<double>& temperature, const thermal::Samples& samples,
                             const std::vector<PartSide>& sides) {
  SideSummaries out;
  struct Sums {
    double w = 0, t = 0, tt = 0, max = -kNone;
  } sums[2];
  for (std::size_t i = 0; i < sides.size(); ++i) {
    Sums& s = sums[sides[i] == PartSide::Core ? 0 : 1];
    const double w = samples.weights[i], t = temperature[i];
    s.w += w, s.t += w * t, s.max = std::max(s.max, t);
  }
  for (std::size_t i = 0; i < sides.size(); ++i) {  // the spread about each side's mean: no cancellation
    Sums& s = sums[sides[i] == PartSide::Core ? 0 : 1];
    if (s.w <= 0) continue;
    const double d = temperature[i] - s.t / s.w;
    s.tt += samples.weights[i] * d * d;
  }
  SideSummary* into[2] = {&out.core, &out.cavity};
  for (int k = 0; k < 2; ++k) {
    if (sums[k].w <= 0) continue;
    *into[k] = {sums[k].w, sums[k].t / sums[k].w, std::sqrt(sums[k].tt / sums[k].w), sums[k].max};
  }
  return out;
}

}  // namespace mtcs::eval
