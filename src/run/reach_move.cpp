#include "reach_move.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "mtcs/geometry/segment_distance.h"
#include "mtcs/mold/decoder.h"

namespace mtcs::run {

using geometry::Vec3;
using mold::axis_of;
using mold::face_plane;

namespace {

using std::numbers::pi;

double nearest_wall(const mold::Layout& layout, const Vec3& p) {
  double best = std::numeric_limits<double>::infinity();
  for (const mold::Bore& b : layout.bores)
    best = std::min(best, geometry::point_segment_distance(p, {b.flow_start, b.flow_end}) - b.diameter / 2);
  return best;
}

// A U circuit with a leg along axis `leg` through `at`, the leg spanning the target along that
// axis: in from the inlet face, along the leg, out to the outlet face. When the leg runs along
// the inlet's own axis, the inlet hole is the leg (it ends past the target) and the circuit
// turns across another drillable axis.
mold::Circuit u_through(const mold::MoldSpec& spec, const geometry::Box& block, const geometry::Box& region,
                        const Vec3& target, const Vec3& at, int leg, double diameter, opt::Rng& rng) {
  const mold::Face in = spec.circuits.inlet_faces[std::size_t(rng.below(int(spec.circuits.inlet_faces.size())))];
  const mold::Face out = spec.circuits.outlet_faces[std::size_t(rng.below(int(spec.circuits.outlet_faces.size())))];
  const int ki = axis_of(in), ko = axis_of(out);
  // How far the leg runs past the target on either side: at least two diameters, up to half the region.
  auto reach = [&](int k) { return 2 * diameter + rng.uniform() * 0.5 * region.size()[k]; };
  mold::Circuit c;
  c.diameter = diameter;
  Vec3 a = at, b = at;
  if (leg != ki) {
    a[leg] = target[leg] - reach(leg);
    b[leg] = target[leg] + reach(leg);
    if (rng.uniform() < 0.5) std::swap(a, b);
    if (ko == leg) {
      // The leg runs out through the outlet face: start it on the far side of the target.
      if (std::abs(a[leg] - face_plane(block, out)) < std::abs(b[leg] - face_plane(block, out))) std::swap(a, b);
      b[leg] = face_plane(block, out);
    }
  } else {
    // The inlet hole is the leg: it ends beyond the target, seen from the inlet face.
    const double inward = face_plane(block, in) <= block.min[ki] + 1e-9 ? 1.0 : -1.0;
    a[leg] = target[leg] + inward * reach(leg);
    std::vector<int> across;
    for (const mold::Face f : spec.drilling.allowed_faces)
      if (axis_of(f) != ki && std::find(across.begin(), across.end(), axis_of(f)) == across.end())
        across.push_back(axis_of(f));
    const int k = across.empty() ? (ki + 1) % 3 : across[std::size_t(rng.below(int(across.size())))];
    b = a;
    b[k] = region.min[k] + rng.uniform() * region.size()[k];
  }
  Vec3 inlet = a;
  inlet[ki] = face_plane(block, in);
  c.waypoints = {inlet, a, b};
  if (std::abs(b[ko] - face_plane(block, out)) > 1e-9) {
    Vec3 outlet = b;
    outlet[ko] = face_plane(block, out);
    c.waypoints.push_back(outlet);
  }
  return c;
}

// The shift that clears one violated clearance (elements[0] the bore): away from the other
// element's closest point, or from the block's nearest face, by the shortfall and a little
// more. `fallback` is the direction used when the two touch. None for a drilling rule.
std::optional<Vec3> clearing_shift(const eval::Violation& v, const geometry::Box& block, const Vec3& fallback) {
  const double extra = 0.1;  // mm beyond the margin: the written layout is rounded to 0.01 mm
  const double by = v.margin - v.distance + extra;
  switch (v.kind) {
    case eval::ViolationKind::BoreCavity:
    case eval::ViolationKind::BoreKeepout: {
      if (!v.closest) return fallback * by;
      const Vec3 away = v.closest->first - v.closest->second;
      return (away.norm() > 1e-9 ? away.normalized() : fallback) * by;
    }
    case eval::ViolationKind::BoreSurface: {
      // Inwards from the block face nearest the place.
      int axis = 0;
      double sign = 1, least = std::numeric_limits<double>::infinity();
      for (int k = 0; k < 3; ++k) {
        if (v.where[k] - block.min[k] < least) least = v.where[k] - block.min[k], axis = k, sign = 1;
        if (block.max[k] - v.where[k] < least) least = block.max[k] - v.where[k], axis = k, sign = -1;
      }
      Vec3 s = Vec3::Zero();
      s[axis] = sign * by;
      return s;
    }
    default:
      return std::nullopt;
  }
}

}  // namespace

double wall_distance(const mold::Scene& scene, const mold::Circuit& circuit, const Vec3& p) {
  return nearest_wall(mold::decode(scene, mold::Genome{{circuit}}), p);
}

Reached circuit_reaching(const eval::Pipeline& pipeline, const ReachRequest& request,
                                              const std::function<void(mold::Circuit&)>& repair, opt::Rng& rng) {
  const mold::Scene& scene = pipeline.scene();
  const mold::MoldSpec& spec = scene.spec();
  const geometry::Box& block = scene.block_bounds();
  std::vector<int> drillable;
  for (const mold::Face f : spec.drilling.allowed_faces)
    if (std::find(drillable.begin(), drillable.end(), axis_of(f)) == drillable.end()) drillable.push_back(axis_of(f));
  if (drillable.empty()) return {};
  const double r = request.diameter / 2;
  const double cavity_margin = spec.clearances.bore_cavity.at(request.diameter);
  int left = request.evaluations;
  while (left > 0) {
    // A start: a leg along a drillable axis, offset from the target in a random direction across
    // it by the least distance the cavity allows (the target is on the cavity's surface).
    const int leg = drillable[std::size_t(rng.below(int(drillable.size())))];
    const int i = (leg + 1) % 3, j = (leg + 2) % 3;
    const double angle = 2 * pi * rng.uniform();
    Vec3 away = Vec3::Zero();
    away[i] = std::cos(angle), away[j] = std::sin(angle);
    mold::Circuit c = u_through(spec, block, request.region, request.target,
                                request.target + (r + cavity_margin) * away, leg, request.diameter, rng);
    repair(c);
    // Pushed out of each clearance it violates, re-scored after every push.
    while (left > 0) {
      --left;
      // Only feasibility is asked: the constraint stages alone, on the one decoding.
      const mold::Layout layout = mold::decode(scene, mold::Genome{{c}});
      const eval::Evaluation e = pipeline.constraints(layout);
      if (nearest_wall(layout, request.target) >= request.better_than) break;  // pushed too far: a new start
      // A circuit's coolant limits (its flow through its diameter) do not move with it: the
      // geometry alone decides here, the full evaluation judges the rest.
      const bool clear = std::all_of(e.violations.begin(), e.violations.end(),
                                     [](const eval::Violation& v) { return !eval::is_geometric(v.kind); });
      if (clear) return {c, request.evaluations - left};
      Vec3 shift = Vec3::Zero();
      bool clearable = true;
      for (const eval::Violation& v : e.violations) {
        if (!eval::is_geometric(v.kind)) continue;
        const auto s = clearing_shift(v, block, away);
        if (!s) {
          clearable = false;
          break;
        }
        // The largest shift along each axis (two violations on one side need one push, not two).
        for (int k = 0; k < 3; ++k)
          if (std::abs((*s)[k]) > std::abs(shift[k])) shift[k] = (*s)[k];
      }
      if (!clearable || shift.norm() < 1e-9) break;
      for (Vec3& p : c.waypoints) p += shift;
      repair(c);
    }
  }
  return {std::nullopt, request.evaluations - left};
}

}  // namespace mtcs::run
