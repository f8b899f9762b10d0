#include "mtcs/mold/decoder.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace mtcs::mold {

using geometry::Vec3;

namespace {

using std::numbers::pi;

bool contains(const std::vector<Face>& faces, Face f) {
  return std::find(faces.begin(), faces.end(), f) != faces.end();
}

// Distance from p to the nearest of the given faces of the block's bounding box.
double off_faces(const Box& b, const Vec3& p, const std::vector<Face>& faces) {
  double best = std::numeric_limits<double>::infinity();
  for (const Face f : faces) best = std::min(best, std::abs(p[axis_of(f)] - face_plane(b, f)));
  return best;
}

struct Candidate {
  Vec3 entry, far_end, near_flow;
  Face face;
  double angle_deg;
  bool allowed, ok, plugged, through;
  double length;
};

// The routed waypoints into `merged`, through `pts` (both cleared first): decode reuses both
// per thread, so a layout's routes allocate nothing.
void route(const Scene& scene, const Circuit& circuit, std::vector<Vec3>& pts, std::vector<Vec3>& merged) {
  pts.clear();
  merged.clear();
  const double tiny = 1e-9 * std::max(1.0, scene.block_bounds().size().maxCoeff());
  const Drilling& drill = scene.spec().drilling;
  // Axes no allowed face lets a drill run along: with axis-parallel holes, a circuit keeps
  // its inlet's coordinate along them.
  std::array<bool, 3> drillable{false, false, false};
  for (const Face f : drill.allowed_faces) drillable[std::size_t(axis_of(f))] = true;
  for (Vec3 p : circuit.waypoints) {
    if (drill.axis_parallel && !pts.empty())
      for (int k = 0; k < 3; ++k)
        if (!drillable[std::size_t(k)]) p[k] = pts.front()[k];
    if (pts.empty()) {
      pts.push_back(p);
      continue;
    }
    Vec3 at = pts.back();
    if (scene.spec().drilling.axis_parallel) {
      // Legs along the axes, longest first.
      std::array<int, 3> order{0, 1, 2};
      const Vec3 delta = p - at;
      std::sort(order.begin(), order.end(), [&](int i, int j) { return std::abs(delta[i]) > std::abs(delta[j]); });
      for (const int k : order) {
        if (std::abs(p[k] - at[k]) <= tiny) continue;
        at[k] = p[k];
        pts.push_back(at);
      }
    } else if ((p - at).norm() > tiny) {
      pts.push_back(p);
    }
  }
  // A waypoint where the path goes straight on is drilled through: one hole, not two.
  for (const Vec3& p : pts) {
    if (merged.size() >= 2) {
      const Vec3 a = merged[merged.size() - 2], b = merged.back();
      const Vec3 u = (b - a).normalized(), v = (p - b).normalized();
      if (u.dot(v) > 1 - 1e-12) merged.back() = p;
      else merged.push_back(p);
    } else {
      merged.push_back(p);
    }
  }
}

}  // namespace

BlindAxis blind_axis(const Scene& scene, const Circuit& circuit) {
  const Box& block = scene.block_bounds();
  const Drilling& drill = scene.spec().drilling;
  if (circuit.waypoints.empty()) return {};
  const Vec3 at = circuit.waypoints.front(), to = circuit.waypoints.back();
  const Face face = nearest_face(block, at, drill.blind_faces());
  const int k = axis_of(face);
  const Vec3 inward = -normal_of(face);
  BlindAxis a;
  a.face = face;
  a.entry = at;
  a.entry[k] = face_plane(block, face);
  for (int j = 0; j < 3; ++j)
    if (j != k) a.entry[j] = std::clamp(a.entry[j], block.min[j], block.max[j]);
  // At least a diameter deep, and the drill point inside the block.
  const double D = circuit.diameter;
  const double deepest = std::max(D, block.size()[k] - drill.point_length(D) - 1e-6 * block.size()[k]);
  const double depth = std::clamp((to - a.entry).dot(inward), D, deepest);
  a.tip = a.entry + depth * inward;
  return a;
}

std::vector<Vec3> routed_waypoints(const Scene& scene, const Circuit& circuit) {
  if (is_blind(circuit.kind)) {
    const BlindAxis a = blind_axis(scene, circuit);
    return {a.entry, a.tip};
  }
  std::vector<Vec3> pts, merged;
  route(scene, circuit, pts, merged);
  return merged;
}

Genome drilled_genome(const Scene& scene, const Genome& genome) {
  Genome out;
  for (const Circuit& c : genome.circuits) {
    Circuit d{routed_waypoints(scene, c), c.diameter, c.kind};
    if (d.waypoints.size() >= 2) out.circuits.push_back(std::move(d));
  }
  return out;
}

Layout decode(const Scene& scene, const Genome& genome) {
  const MoldSpec& spec = scene.spec();
  const Drilling& drill = spec.drilling;
  const double port_tol = 1e-6 * std::max(1.0, scene.block_bounds().size().maxCoeff());
  Layout layout;
  std::size_t waypoints = 0;
  for (const Circuit& circuit : genome.circuits) waypoints += circuit.waypoints.size();
  layout.bores.reserve(waypoints);  // one leg per waypoint, as most routes have: not a growth by doublings
  layout.junctions.reserve(waypoints);
  static thread_local std::vector<Vec3> legs, pts;
  for (std::size_t c = 0; c < genome.circuits.size(); ++c) {
    const Circuit& circuit = genome.circuits[c];
    if (is_blind(circuit.kind)) {
      if (circuit.waypoints.empty()) continue;
      const BlindAxis a = blind_axis(scene, circuit);
      // Entered where the block's surface is (a mesh block's may lie inside its bounding box).
      const BlockExit e = scene.exit_block(a.tip, normal_of(a.face));
      const Vec3 entry = e.hit ? e.point : a.entry;
      Bore b;
      b.hole = {entry, a.tip - drill.point_length(circuit.diameter) * normal_of(a.face), circuit.diameter / 2};
      b.flow_start = entry;
      b.flow_end = a.tip;
      b.entry_face = a.face;
      b.entry_allowed = contains(drill.blind_faces(), a.face);
      b.drilled_length = (b.hole.p1 - b.hole.p0).norm();
      b.diameter = circuit.diameter;
      b.circuit = int(c);
      b.kind = circuit.kind;
      if (circuit.kind == CircuitKind::Bubbler) {
        static const BaffleSpec kDefaultTube;
        const BaffleSpec& tube = drill.baffles ? *drill.baffles : kDefaultTube;
        b.tube_outer = tube.tube_outer * circuit.diameter, b.tube_inner = tube.tube_inner * circuit.diameter;
      }
      layout.bores.push_back(b);
      continue;
    }
    route(scene, circuit, legs, pts);
    if (pts.size() < 2) continue;
    const double inlet_off = off_faces(scene.block_bounds(), pts.front(), spec.circuits.inlet_faces);
    const double outlet_off = off_faces(scene.block_bounds(), pts.back(), spec.circuits.outlet_faces);
    if (inlet_off > port_tol) layout.ports.push_back({int(c), true, inlet_off});
    if (outlet_off > port_tol) layout.ports.push_back({int(c), false, outlet_off});

    const double D = circuit.diameter;
    const double overshoot = drill.point_length(D) + drill.min_overlap;
    const int n = int(pts.size()) - 1;  // flow segments
    const int first = int(layout.bores.size());
    for (int j = 1; j <= n; ++j) {
      const Vec3 A = pts[std::size_t(j - 1)], B = pts[std::size_t(j)];
      const Vec3 u = (B - A).normalized();
      auto make = [&](const Vec3& from, const Vec3& dir, const Vec3& far_end, bool at_port, bool ends_at_port) {
        const BlockExit e = scene.exit_block(from, dir);
        Candidate k;
        k.entry = e.hit ? e.point : from;
        k.near_flow = from;
        k.far_end = far_end;
        k.face = face_of_normal(e.normal);
        k.angle_deg = std::acos(std::clamp(std::abs(dir.dot(e.normal.normalized())), 0.0, 1.0)) * 180 / pi;
        k.allowed = contains(drill.allowed_faces, k.face);
        k.ok = k.allowed && k.angle_deg <= drill.max_angle_deg + 1e-9;
        k.plugged = !at_port;
        k.through = ends_at_port;
        k.length = (k.far_end - k.entry).norm();
        return k;
      };
      // From A's side (ending past B), or from B's side (ending past A).
      // A hole ending at a port that lies on its face is drilled through: open at that end.
      const Candidate from_a = make(A, -u, j == n ? B : B + overshoot * u, j == 1, j == n && outlet_off <= port_tol);
      const Candidate from_b = make(B, u, j == 1 ? A : A - overshoot * u, j == n, j == 1 && inlet_off <= port_tol);
      const bool take_a = from_a.ok != from_b.ok ? from_a.ok : from_a.length <= from_b.length;
      const Candidate& k = take_a ? from_a : from_b;
      Bore b;
      b.hole = {k.entry, k.far_end, D / 2};
      b.flow_start = A;
      b.flow_end = B;
      b.entry_face = k.face;
      b.entry_angle_deg = k.angle_deg;
      b.entry_allowed = k.allowed;
      b.plugged = k.plugged;
      b.through = k.through;
      b.dead_end = k.plugged ? (k.near_flow - k.entry).norm() : 0.0;
      b.drilled_length = k.length;
      b.diameter = D;
      b.circuit = int(c);
      b.segment = j - 1;
      layout.plugs += b.plugged ? 1 : 0;
      layout.bores.push_back(b);
      if (j > 1) layout.junctions.push_back({first + j - 2, first + j - 1});
    }
  }
  return layout;
}

}  // namespace mtcs::mold
