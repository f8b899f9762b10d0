// How MoldProblem ranks a layout for SMS-EMOA under each penalty variant: constrained domination
// keeps the score; the static penalties add weight x CV (or CV^2), in scaled units, to every
// objective; death makes an infeasible layout infinitely bad. Checked on a layout through an
// ejector pin of the demo plate against its own evaluation.

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <limits>
#include <set>
#include <string>

#include "mtcs/run/mold_problem.h"
#include "mtcs/eval/pipeline.h"
#include "mtcs/mold/decoder.h"
#include "mtcs/mold/scene.h"
#include "run/violation_text.h"
#include "support/paths.h"

using namespace mtcs;

namespace {

// One U circuit in the z = 50 plane whose first leg runs along y through ejector0 (x = 60, y = 35).
mold::Genome through_ejector() {
  mold::Circuit c;
  c.diameter = 8;
  c.waypoints = {{60, 0, 50}, {60, 100, 50}, {150, 100, 50}, {150, 0, 50}};
  return {{c}};
}

opt::Score ranked(mold::PenaltyVariant variant, double weight, opt::Score* score) {
  mold::MoldSpec spec = mold::load_mold_spec(MTCS_SOURCE_DIR + "/molds/plate.yaml");
  spec.penalty.variant = variant;
  spec.penalty.weight = weight;
  const mold::Scene scene(spec);
  const eval::Pipeline pipeline(scene);
  const run::MoldProblem problem(pipeline, {}, {});
  *score = problem.evaluate(problem.encode(through_ejector()));
  return problem.ranking(*score);
}

}  // namespace

TEST_CASE("MoldProblem ranks an infeasible layout as its penalty variant says", "[run][penalty]") {
  opt::Score s;
  const opt::Score cd = ranked(mold::PenaltyVariant::ConstrainedDomination, 1, &s);
  REQUIRE_FALSE(s.feasible);
  REQUIRE(s.violation > 0);
  CHECK_FALSE(cd.feasible);
  CHECK(cd.objectives == s.objectives);
  CHECK(cd.violation == s.violation);

  // The mold's scale of each of its objectives (plate.yaml: temperature_std, cycle_time, cost).
  const mold::MoldSpec spec = mold::load_mold_spec(MTCS_SOURCE_DIR + "/molds/plate.yaml");
  std::vector<double> scales;
  for (const auto o : spec.objectives.use) scales.push_back(spec.objectives.scale(o));
  REQUIRE(scales.size() == s.objectives.size());
  const opt::Score linear = ranked(mold::PenaltyVariant::StaticLinear, 3, &s);
  CHECK(linear.feasible);
  CHECK(linear.violation == 0);
  for (std::size_t k = 0; k < 3; ++k)
    CHECK(linear.objectives[k] == Approx(s.objectives[k] + 3 * s.violation * scales[k]).epsilon(1e-14));
  const opt::Score quadratic = ranked(mold::PenaltyVariant::StaticQuadratic, 3, &s);
  for (std::size_t k = 0; k < 3; ++k)
    CHECK(quadratic.objectives[k] == Approx(s.objectives[k] + 3 * s.violation * s.violation * scales[k]).epsilon(1e-14));
  const opt::Score death = ranked(mold::PenaltyVariant::Death, 1, &s);
  CHECK(death.feasible);
  for (const double v : death.objectives) CHECK(std::isinf(v));
}

// mutation.blend: circuits of the same shape in both parents get SBX-blended hole coordinates.
// Against the operator's definition: holes stay aligned (each aligned run moves as one), each
// hole takes b's side with probability 1/2, SBX (eta 10) lands inside the parents' span half
// the time (its spread factor's median is 1), the ports stay on their faces, and the same draws
// give the same child; circuits of different shapes fall back to the whole-circuit crossover.
TEST_CASE("MoldProblem blends the hole coordinates of parents that share a circuit's shape", "[run][blend]") {
  const mold::MoldSpec spec = mold::load_mold_spec(MTCS_SOURCE_DIR + "/molds/plate.yaml");
  REQUIRE(spec.drilling.axis_parallel);
  const mold::Scene scene(spec);
  const eval::Pipeline pipeline(scene);
  run::MutationRates rates;
  rates.blend = 1;
  const run::MoldProblem problem(pipeline, {}, rates);
  const mold::Genome ga = through_ejector();
  mold::Genome gb = ga;
  gb.circuits[0].waypoints = {{70, 0, 55}, {70, 100, 55}, {140, 100, 55}, {140, 0, 55}};
  const opt::Genotype a = problem.encode(ga), b = problem.encode(gb);
  // The holes as variables: (waypoint, axis) of each run's first point, and a's and b's values.
  struct Hole { std::size_t first, last; int k; double va, vb; };
  std::vector<Hole> holes;
  for (int k = 0; k < 3; ++k) {
    std::size_t i = 0;
    const auto& w = ga.circuits[0].waypoints;
    while (i < w.size()) {
      std::size_t j = i + 1;
      while (j < w.size() && w[j][k] == w[i][k]) ++j;
      holes.push_back({i, j, k, w[i][k], gb.circuits[0].waypoints[i][k]});
      i = j;
    }
  }
  int changed = 0, inside = 0, variables = 0;
  for (std::uint64_t seed = 1; seed <= 400; ++seed) {
    opt::Rng rng(seed), again(seed);
    const opt::Genotype child = problem.recombine(a, b, rng);
    REQUIRE(problem.recombine(a, b, again) == child);
    const auto w = problem.genome(child).circuits.at(0).waypoints;
    REQUIRE(w.size() == 4);
    CHECK(w.front().y() == 0);  // inlet and outlet on the y = 0 face
    CHECK(w.back().y() == 0);
    for (const Hole& h : holes) {
      for (std::size_t m = h.first + 1; m < h.last; ++m) CHECK(w[m][h.k] == w[h.first][h.k]);
      if (h.va == h.vb) {
        CHECK(w[h.first][h.k] == h.va);
        continue;
      }
      ++variables;
      const double v = w[h.first][h.k];
      if (v == h.va) continue;
      ++changed;
      inside += v > std::min(h.va, h.vb) && v < std::max(h.va, h.vb);
    }
  }
  CHECK(changed == Approx(0.5 * variables).epsilon(0.1));
  CHECK(inside == Approx(0.5 * changed).epsilon(0.15));

  // A different shape (an extra waypoint in b): whole circuits, a's or b's, as without blend.
  mold::Genome gc = gb;
  gc.circuits[0].waypoints.insert(gc.circuits[0].waypoints.begin() + 2, {70, 100, 80});
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    opt::Rng rng(seed);
    const auto w = problem.genome(problem.recombine(a, problem.encode(gc), rng)).circuits.at(0).waypoints;
    CHECK((w == ga.circuits[0].waypoints || w == gc.circuits[0].waypoints));
  }
}

// mutation.jog on an axis-parallel U: one segment split by a new leg across it in the circuit's
// plane, the segment's far end slid across with it, so the route stays axis-parallel, the ports
// stay on their face and the layout gains two bores. Every segment and both in-plane axes occur.
TEST_CASE("MoldProblem's jog splits a segment by a leg across it", "[run][jog]") {
  const mold::MoldSpec spec = mold::load_mold_spec(MTCS_SOURCE_DIR + "/molds/plate.yaml");
  REQUIRE(spec.drilling.axis_parallel);
  const mold::Scene scene(spec);
  const eval::Pipeline pipeline(scene);
  run::MutationRates rates;
  rates.insert = rates.remove = rates.snap = rates.diameter = rates.circuit = rates.reach = 0;
  rates.moves = 0;  // every hole moves, by sigma = 0 below: only the jog changes the circuit
  rates.jog = 1;
  const run::MoldProblem problem(pipeline, {}, rates);
  const mold::Genome parent = through_ejector();
  const auto& u = parent.circuits[0].waypoints;
  const std::size_t bores = mold::decode(scene, parent).bores.size();
  const geometry::Box& box = scene.block_bounds();
  std::set<std::pair<std::size_t, int>> seen;  // (segment, axis across)
  for (std::uint64_t seed = 1; seed <= 200; ++seed) {
    opt::Rng rng(seed);
    opt::Genotype x = problem.encode(parent);
    problem.mutate(x, {0.0}, rng);
    const mold::Genome child = problem.genome(x);
    const auto& w = child.circuits.at(0).waypoints;
    REQUIRE(w.size() == u.size() + 2);
    CHECK(w.front() == u.front());  // the inlet stays
    CHECK(w.back().y() == box.min.y());  // the outlet stays on its face
    for (std::size_t i = 0; i + 1 < w.size(); ++i) {
      INFO("seed " << seed << ", segment " << i);
      int differ = 0;
      for (int k = 0; k < 3; ++k) differ += w[i][k] != w[i + 1][k];
      CHECK(differ <= 1);  // axis-parallel
      CHECK(w[i].z() == u[0].z());  // in the inlet's drilling plane
    }
    // The split segment: the first waypoint that left the parent's route.
    std::size_t s = 0;
    while (s < u.size() && w[s] == u[s]) ++s;
    REQUIRE(s >= 1);
    REQUIRE(s < u.size());
    const geometry::Vec3 a = u[s - 1], b = u[s], p = w[s], q = w[s + 1];
    CHECK((p - a).norm() + (b - p).norm() == Approx((b - a).norm()).epsilon(1e-12));  // p on the segment
    int across = -1;
    for (int k = 0; k < 3; ++k)
      if (q[k] != p[k]) across = k;
    REQUIRE(across >= 0);
    CHECK(q[across] >= box.min[across]);
    CHECK(q[across] <= box.max[across]);
    CHECK(w[s + 2][across] == q[across]);  // the far end slid across
    seen.insert({s - 1, across});
    // Two more bores, each drillable from the plate's faces.
    const mold::Layout layout = mold::decode(scene, child);
    CHECK(layout.bores.size() == bores + 2);
  }
  // Each of the U's three segments, across in x or y as its axis allows: (0, x), (1, y), (2, x).
  CHECK(seen == std::set<std::pair<std::size_t, int>>{{0, 0}, {1, 1}, {2, 0}});
}

TEST_CASE("MoldProblem's violation detail is printf's %.6g of each distance and margin", "[run][detail]") {
  // The run store keeps this text; it is written without printf (it is built for every child).
  const mold::MoldSpec spec = mold::load_mold_spec(MTCS_SOURCE_DIR + "/molds/plate_wall_distance.yaml");
  const mold::Scene scene(spec);
  const eval::Pipeline pipeline(scene);
  const run::MoldProblem problem(pipeline, {}, {});
  opt::Rng rng(20261128);
  int violations = 0;
  for (int k = 0; k < 200; ++k) {
    const opt::Genotype g = problem.sample(rng);
    const eval::Evaluation e = pipeline.evaluate(problem.genome(g));
    std::string expected;
    for (const auto& v : e.violations) {
      if (!expected.empty()) expected += "; ";
      expected += eval::to_string(v.kind);
      for (const auto& el : v.elements) expected += ' ' + el;
      char num[64];
      std::snprintf(num, sizeof num, " %.6g/%.6g", v.distance, v.margin);
      expected += num;
      ++violations;
    }
    CHECK(problem.evaluate(g).detail == expected);
  }
  CHECK(violations > 100);
}

TEST_CASE("append_general6 writes what printf's %.6g writes", "[run][detail]") {
  const double values[] = {0.0, -0.0, 1.0, 2.5, 999999.5, 9999995.0, 1e6, 1e-5, 1.234565e-5, 0.1 + 0.2,
                           -123.456789, 6.02214076e23, std::numeric_limits<double>::denorm_min(),
                           std::numeric_limits<double>::min(), -std::numeric_limits<double>::max(),
                           std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                           std::numeric_limits<double>::quiet_NaN(), -std::numeric_limits<double>::quiet_NaN()};
  for (const double x : values) {
    char expected[64];
    std::snprintf(expected, sizeof expected, "%.6g", x);
    std::string got = "x";
    run::append_general6(got, x);
    CHECK(got == "x" + std::string(expected));
  }
}
