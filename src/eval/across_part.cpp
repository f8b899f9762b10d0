#include "mtcs/eval/across_part.h"

#include <cmath>

namespace mtcs::eval {

using geometry::Vec3;

namespace {
constexpr double kOpposite = -0.8;  // the faces' normals' dot product at most: within 37 degrees
}  // namespace

std::vector<std::optional<Vec3>> across_part(const mold::Scene& scene, const thermal::Samples& samples, double reach) {
  std::vector<std::optional<Vec3>> out(samples.size());
  const auto& cavity = scene.spec().cavity;
  if (!cavity || cavity->is_patch() || samples.normals.size() != samples.size()) return out;
  const mesh::TriangleBvh* bvh = scene.cavity_bvh();
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const Vec3& p = samples.points[i];
    const Vec3& n = samples.normals[i];
    if (n.squaredNorm() < 0.5) continue;
    if (cavity->box) {  // the part is the box: straight across along the normal's axis
      int axis = 0;
      n.cwiseAbs().maxCoeff(&axis);
      const double t = cavity->box->size()[axis];
      if (t <= reach) out[i] = Vec3(p - t * n);
      continue;
    }
    if (!bvh) continue;
    // From a hair inside the part, so the sample's own face is not the first crossing.
    const double start = 1e-6 * (1 + bvh->bounds().size().norm());
    const auto hit = bvh->first_hit(p - start * n, -n);
    if (hit && hit->t + start <= reach && hit->normal.dot(n) <= kOpposite) out[i] = Vec3(p - (hit->t + start) * n);
  }
  return out;
}

void append_across(thermal::Samples& samples, const std::vector<std::optional<Vec3>>& across) {
  for (std::size_t i = 0; i < across.size(); ++i) {
    if (!across[i]) continue;
    samples.points.push_back(*across[i]);
    samples.weights.push_back(0);
    if (!samples.thickness.empty()) samples.thickness.push_back(samples.thickness[i]);
    if (samples.normals.size() + 1 == samples.points.size()) samples.normals.push_back(-samples.normals[i]);
  }
}

WallDifference wall_difference(const std::vector<double>& at_samples, const std::vector<double>& at_across,
                               const thermal::Samples& samples, const std::vector<std::optional<Vec3>>& across) {
  WallDifference d;
  double sum = 0;
  for (std::size_t i = 0, k = 0; i < across.size(); ++i) {
    if (!across[i]) continue;
    const double diff = std::abs(at_samples[i] - at_across[k++]);
    d.pairs += 1, d.paired_area += samples.weights[i], sum += samples.weights[i] * diff;
    if (diff > d.max) d.max = diff, d.where = samples.points[i];
  }
  if (d.paired_area > 0) d.mean = sum / d.paired_area;
  return d;
}

}  // namespace mtcs::eval
