#include "mtcs/mold/scene.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "mtcs/mesh/wall_thickness.h"

namespace mtcs::mold {

using geometry::Vec3;

namespace {
constexpr double kThickestWall = 1e3;  // mm: the inscribed balls' cap
}  // namespace

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
  if (spec_.cavity && spec_.cavity->local_thickness && cavity_bvh_ && !spec_.cavity->mesh->mesh.triangles.empty()) {
    const mesh::TriangleMesh& m = spec_.cavity->mesh->mesh;
    cavity_thickness_.resize(m.triangles.size());
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
      const Vec3 a = m.corner(t, 0), b = m.corner(t, 1), c = m.corner(t, 2);
      cavity_thickness_[t] = mesh::inscribed_diameter(*cavity_bvh_, (a + b + c) / 3, (b - a).cross(c - a).normalized(), kThickestWall);
    }
    const double thickest = *std::max_element(cavity_thickness_.begin(), cavity_thickness_.end());
    if (!(thickest > 0))
      throw std::invalid_argument("cavity.wall_thickness: local: no wall across the part's mesh (is it closed?)");
    for (double& s : cavity_thickness_) s = s > 0 ? s : thickest;  // a sliver the ray slipped past
    spec_.cavity->wall_thickness = thickest;
  }
}

double Scene::wall_thickness_at(const Vec3& p, const Vec3& outward) const {
  if (!spec_.cavity) return Cavity{}.wall_thickness;
  const Cavity& c = *spec_.cavity;
  if (!c.local_thickness || !cavity_bvh_) return c.wall_thickness;
  const double s = mesh::inscribed_diameter(*cavity_bvh_, p, outward, kThickestWall);
  return s > 0 ? s : c.wall_thickness;
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
