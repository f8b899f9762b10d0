#include "mtcs/run/shop_layout.h"

#include <cmath>
#include <vector>

#include "holes.h"
#include "mtcs/io/number_text.h"
#include "mtcs/mold/decoder.h"

namespace mtcs::run {

using geometry::Vec3;

namespace {

// The same holes, to a hair: a merge that changes the drilling plan is not a merge.
bool same_plan(const mold::Layout& a, const mold::Layout& b) {
  if (a.bores.size() != b.bores.size()) return false;
  for (std::size_t i = 0; i < a.bores.size(); ++i) {
    const auto& p = a.bores[i];
    const auto& q = b.bores[i];
    if ((p.hole.p0 - q.hole.p0).norm() > 1e-9 || (p.hole.p1 - q.hole.p1).norm() > 1e-9 || p.diameter != q.diameter ||
        p.plugged != q.plugged)
      return false;
  }
  return true;
}

// Whether b lies on the straight run from a to c (within tol), between them.
bool on_run(const Vec3& a, const Vec3& b, const Vec3& c, double tol) {
  const Vec3 ac = c - a;
  const double len2 = ac.squaredNorm();
  if (len2 == 0) return (b - a).norm() <= tol;
  const double t = (b - a).dot(ac) / len2;
  return t >= 0 && t <= 1 && (a + t * ac - b).norm() <= tol;
}

// Waypoints of one circuit that share a coordinate and move together when rounding is undone:
// one hole drilled along the other axes. Runs touching a block face stay put (ports keep their faces).
struct Run {
  std::size_t circuit;
  int axis;
  std::size_t first, last;
};

std::vector<Run> movable_runs(const mold::Genome& g, const geometry::Box& box) {
  std::vector<Run> runs;
  for (std::size_t ci = 0; ci < g.circuits.size(); ++ci) {
    const auto& w = g.circuits[ci].waypoints;
    for (int k = 0; k < 3; ++k)
      for (const auto& [first, last] : aligned_runs(w, k)) {
        bool on_face = false;
        for (std::size_t m = first; m < last; ++m)
          on_face = on_face || std::abs(w[m][k] - box.min[k]) <= 1e-9 || std::abs(w[m][k] - box.max[k]) <= 1e-9;
        if (!on_face) runs.push_back({ci, k, first, last});
      }
  }
  return runs;
}

}  // namespace

mold::Genome shop_layout(const mold::Scene& scene, const mold::Genome& genome, double tolerance) {
  const geometry::Box& box = scene.block_bounds();
  // What the decoder drills, so that the file re-reads as written (no axis it could not drill).
  mold::Genome g = mold::drilled_genome(scene, genome);
  for (auto& c : g.circuits)
    for (Vec3& p : c.waypoints)
      for (int k = 0; k < 3; ++k) {
        const bool on_face = std::abs(p[k] - box.min[k]) <= 1e-9 || std::abs(p[k] - box.max[k]) <= 1e-9;
        if (!on_face) p[k] = io::round_to(p[k], tolerance);
      }
  // Merge: drop an interior waypoint that is a repeat or on the straight run of its neighbours,
  // when the plan decoded stays the same.
  mold::Layout plan = mold::decode(scene, g);
  for (auto& c : g.circuits) {
    for (std::size_t i = 1; i + 1 < c.waypoints.size();) {
      const Vec3 &a = c.waypoints[i - 1], &b = c.waypoints[i], &d = c.waypoints[i + 1];
      if (!on_run(a, b, d, 1e-9)) {
        ++i;
        continue;
      }
      mold::Circuit before = c;
      c.waypoints.erase(c.waypoints.begin() + std::ptrdiff_t(i));
      mold::Layout merged = mold::decode(scene, g);
      if (same_plan(plan, merged)) {
        plan = std::move(merged);
      } else {
        c = std::move(before);
        ++i;
      }
    }
  }
  return g;
}

mold::Genome shop_layout(const MoldProblem& problem, const mold::Scene& scene, const mold::Genome& genome,
                         double tolerance) {
  mold::Genome g = shop_layout(scene, genome, tolerance);
  opt::Score score = problem.evaluate(problem.encode(g));
  if (score.feasible || !problem.evaluate(problem.encode(genome)).feasible) return g;
  // Rounding pushed a hole across a clearance: step runs one rounding step at a time, keeping a
  // step that lowers the violation, until the layout is feasible again (a few passes at most).
  for (int pass = 0; pass < 4 && !score.feasible; ++pass) {
    bool moved = false;
    for (const Run& run : movable_runs(g, scene.block_bounds())) {
      if (score.feasible) break;
      mold::Circuit& c = g.circuits[run.circuit];
      for (const double step : {tolerance, -tolerance}) {
        const mold::Circuit before = c;
        for (std::size_t m = run.first; m < run.last; ++m)
          c.waypoints[m][run.axis] = io::round_to(c.waypoints[m][run.axis] + step, tolerance);
        const opt::Score shifted = problem.evaluate(problem.encode(g));
        if (shifted.violation < score.violation) {
          score = shifted, moved = true;
          break;
        }
        c = before;
      }
    }
    if (!moved) break;
  }
  return g;
}

mold::Layout shop_plan(const mold::Layout& layout, double tolerance) {
  mold::Layout out = layout;
  const auto round = [&](Vec3& p) {
    for (int k = 0; k < 3; ++k) p[k] = io::round_to(p[k], tolerance);
  };
  for (mold::Bore& b : out.bores) {
    round(b.hole.p0), round(b.hole.p1), round(b.flow_start), round(b.flow_end);
    b.drilled_length = io::round_to((b.hole.p1 - b.hole.p0).norm(), tolerance);
    b.dead_end = io::round_to(b.dead_end, tolerance);
  }
  return out;
}

}  // namespace mtcs::run
