#include "mtcs/mold/scene.h"

#include <cmath>
#include <limits>

namespace mtcs::mold {

using geometry::Vec3;

Scene::Scene(MoldSpec spec) : spec_(std::move(spec)) {
  if (spec_.block.box) {
    block_bounds_ = *spec_.block.box;
  } else {
    block_bounds_ = spec_.block.mesh->mesh.bounds();
    block_bvh_ = std::make_unique<mesh::TriangleBvh>(spec_.block.mesh->mesh);
  }
  if (spec_.cavity && spec_.cavity->mesh) cavity_bvh_ = std::make_unique<mesh::TriangleBvh>(spec_.cavity->mesh->mesh);
  for (const KeepOut& k : spec_.keep_outs)
    keep_out_bvh_.push_back(k.mesh ? std::make_unique<mesh::TriangleBvh>(k.mesh->mesh) : nullptr);
}

BlockExit Scene::exit_block(const Vec3& from, const Vec3& d) const {
  if (block_bvh_) {
    const auto hit = block_bvh_->first_hit(from, d);
    if (!hit) return {from, -d, false};
    return {from + hit->t * d, hit->normal, true};
  }
  const Box& b = block_bounds_;
  double t = std::numeric_limits<double>::infinity();
  int axis = -1;
  for (int k = 0; k < 3; ++k) {
    if (d[k] == 0) continue;
    const double tk = ((d[k] > 0 ? b.max[k] : b.min[k]) - from[k]) / d[k];
    if (tk < t) t = tk, axis = k;
  }
  if (axis < 0 || !(t >= 0)) return {from, -d, false};
  Vec3 n = Vec3::Zero();
  n[axis] = d[axis] > 0 ? 1 : -1;
  return {from + t * d, n, true};
}

double Scene::surface_clearance(const geometry::Cylinder& c, double skip, double cap, double skip_end) const {
  const Vec3 axis = c.p1 - c.p0;
  const double len = axis.norm();
  if (len == 0) return cap;
  if (skip_end > 0 && skip + skip_end >= len) return cap;  // both ends exempt: nothing left to check
  const Vec3 u = axis / len;
  const Vec3 s0 = c.p0 + std::min(skip, len) * u, s1 = c.p1 - skip_end * u;
  if (block_bvh_) {
    if (!block_bvh_->contains(s0) || !block_bvh_->contains(s1)) return -c.radius;
    return std::min(cap, block_bvh_->segment_distance(s0, s1, cap + c.radius) - c.radius);
  }
  // Box: each face plane, with the cylinder's reach towards it, r sqrt(1 - (u.n)^2).
  double d = cap;
  for (int k = 0; k < 3; ++k) {
    const double reach = c.radius * std::sqrt(std::max(0.0, 1 - u[k] * u[k]));
    d = std::min(d, std::min(s0[k], s1[k]) - block_bounds_.min[k] - reach);
    d = std::min(d, block_bounds_.max[k] - std::max(s0[k], s1[k]) - reach);
  }
  return d;
}

Vec3 Scene::surface_place(const geometry::Cylinder& c, double skip, double skip_end) const {
  const Vec3 axis = c.p1 - c.p0;
  const double len = axis.norm();
  if (len == 0) return c.p0;
  const Vec3 u = axis / len;
  const Vec3 s0 = c.p0 + std::min(skip, len) * u, s1 = c.p1 - std::min(skip_end, len) * u;
  if (block_bvh_) {
    if (!block_bvh_->contains(s0)) return s0;
    if (!block_bvh_->contains(s1)) return s1;
    const auto d = block_bvh_->cylinder_distance({s0, s1, c.radius}, std::numeric_limits<double>::infinity());
    return (d.on_cylinder + d.on_triangle) / 2;
  }
  // Box: the face with the least steel in front of the checked stretch, at the stretch's end
  // nearest to it; the bore's wall is `reach` closer to the face than the axis.
  double best = std::numeric_limits<double>::infinity();
  Vec3 place = s0;
  for (int k = 0; k < 3; ++k) {
    const double reach = c.radius * std::sqrt(std::max(0.0, 1 - u[k] * u[k]));
    for (const bool high : {false, true}) {
      const Vec3& end = (s0[k] < s1[k]) != high ? s0 : s1;
      const double plane = high ? block_bounds_.max[k] : block_bounds_.min[k];
      const double gap = (high ? plane - end[k] : end[k] - plane) - reach;
      if (gap >= best) continue;
      best = gap;
      place = end;
      const double wall = high ? end[k] + reach : end[k] - reach;
      place[k] = (wall + plane) / 2;
    }
  }
  return place;
}

}  // namespace mtcs::mold
