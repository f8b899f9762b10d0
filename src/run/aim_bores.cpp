// AM-guided drilling directions: blocked bores turned about their entry to free cells.

#include "aim_bores.h"

#include <algorithm>
#include <cmath>

#include "mtcs/mold/decoder.h"

namespace mtcs::run {

using geometry::Vec3;

namespace {

// The index of the waypoint at p (decoded flow ends are copies of waypoints), or -1.
int waypoint_at(const std::vector<Vec3>& w, const Vec3& p) {
  for (std::size_t i = 0; i < w.size(); ++i)
    if (w[i] == p) return int(i);
  return -1;
}

// The waypoints after turning the bore between w[n] (entry side) and w[f] to direction `to`
// about `entry`: w[n] and w[f] keep their distances from the entry, and the rest of the circuit
// beyond each moves with it (so the other bores keep their directions). Empty when an interior
// waypoint would come closer than `inset` to the block's faces.
std::vector<Vec3> turned(std::vector<Vec3> w, int n, int f, const Vec3& entry, const Vec3& to, const geometry::Box& inner) {
  const Vec3 dn = entry + (w[std::size_t(n)] - entry).norm() * to - w[std::size_t(n)];
  const Vec3 df = entry + (w[std::size_t(f)] - entry).norm() * to - w[std::size_t(f)];
  const int step = f > n ? 1 : -1;
  for (int i = f; i >= 0 && i < int(w.size()); i += step) w[std::size_t(i)] += df;
  for (int i = n; i >= 0 && i < int(w.size()); i -= step) w[std::size_t(i)] += dn;
  for (std::size_t i = 1; i + 1 < w.size(); ++i)
    if ((w[i].array() < inner.min.array()).any() || (w[i].array() > inner.max.array()).any()) return {};
  return w;
}

}  // namespace

int aim_bores(const eval::DrillAccess& access, const mold::Scene& scene, mold::Circuit& circuit, opt::Rng& rng) {
  const double cell = M_PI / access.spec().rows;
  // Interior waypoints stay this far inside the block (bore_surface plus the radius).
  const Vec3 inset = Vec3::Constant(scene.spec().clearances.bore_surface + circuit.diameter / 2);
  const geometry::Box inner{scene.block_bounds().min + inset, scene.block_bounds().max - inset};
  int count = 0;
  for (int j = 0;; ++j) {
    const mold::Layout layout = mold::decode(scene, mold::Genome{{circuit}});
    if (j >= int(layout.bores.size())) break;
    const mold::Bore& b = layout.bores[std::size_t(j)];
    if (!b.entry_allowed || access.check(b).free) continue;
    const Vec3 entry = b.hole.p0;
    const int a = waypoint_at(circuit.waypoints, b.flow_start), z = waypoint_at(circuit.waypoints, b.flow_end);
    if (a < 0 || z < 0) continue;
    // The waypoint on the entry's side is n, the far one f.
    const bool from_a = (circuit.waypoints[std::size_t(a)] - entry).norm() <= (circuit.waypoints[std::size_t(z)] - entry).norm();
    const int n = from_a ? a : z, f = from_a ? z : a;
    const auto free = access.free_directions(entry, b.entry_face, b.diameter, b.drilled_length);
    const Vec3 d = (b.hole.p1 - b.hole.p0).normalized();
    std::vector<std::pair<double, std::vector<Vec3>>> options;  // angle from d, the turned waypoints
    for (const auto& fd : free) {
      std::vector<Vec3> w = turned(circuit.waypoints, n, f, entry, fd.direction, inner);
      if (!w.empty()) options.emplace_back(std::acos(std::clamp(fd.direction.dot(d), -1.0, 1.0)), std::move(w));
    }
    if (options.empty()) continue;
    double nearest = options.front().first;
    for (const auto& o : options) nearest = std::min(nearest, o.first);
    std::vector<std::size_t> near;
    for (std::size_t k = 0; k < options.size(); ++k)
      if (options[k].first <= nearest + 2 * cell) near.push_back(k);
    circuit.waypoints = std::move(options[near[std::size_t(rng.below(int(near.size())))]].second);
    ++count;
  }
  return count;
}

}  // namespace mtcs::run
