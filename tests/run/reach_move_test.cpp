// The reach move (src/run/reach_move.h): the sample a layout cools worst, and a circuit laid
// beside it that the pipeline calls feasible. The small case is the first mold's trough in
// miniature: the top of a box cavity under a sprue, where an 8 mm bore fits only with its axis
// in a 1 mm band (z 52-53: cavity top 40 + bore_cavity 1.0 D + r; block top 60 - bore_surface 3
// - r) and 11 mm or more to the side of the sprue's axis (its radius 4 + clearance 3 + r).

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include <unistd.h>

#include "mtcs/eval/pipeline.h"
#include "mtcs/eval/thermal_model.h"
#include "mtcs/eval/worst_covered.h"
#include "mtcs/geometry/segment_distance.h"
#include "mtcs/mold/decoder.h"
#include "mtcs/mold/scene.h"
#include "mtcs/opt/evolution_strategy.h"
#include "mtcs/opt/sms_emoa.h"
#include "mtcs/run/mold_problem.h"
#include "mtcs/run/session.h"
#include "run/reach_move.h"
#include "support/scratch_file.h"
#include "support/paths.h"

using namespace mtcs;
using geometry::Vec3;

namespace {

mold::MoldSpec trough_spec() {
  const auto dir = mtcs_test::scratch_dir("reach");
  const auto p = dir / "trough.yaml";
  std::ofstream(p) << "block: {box: {min: [0, 0, 0], max: [120, 120, 60]}}\n"
                      "cavity: {box: {min: [30, 30, 10], max: [90, 90, 40]}, sample_spacing: 5}\n"
                      "keep_outs:\n"
                      "  - {name: sprue, cylinder: {p0: [60, 60, 40], p1: [60, 60, 60], radius: 4}, clearance: 3}\n"
                      "drilling: {diameters: [8], axis_parallel: true, allowed_faces: [+x, -x, +y, -y]}\n"
                      "clearances: {bore_bore: 4, bore_cavity: 1.0D, bore_surface: 3}\n"
                      "circuits: {min: 1, max: 3, waypoints: [2, 12], inlet_faces: [-y], outlet_faces: [-y]}\n"
                      "objectives: {use: [uniformity, worst_covered, cost]}\n";
  mold::MoldSpec spec = mold::load_mold_spec(p.string());
  std::filesystem::remove_all(dir);
  return spec;
}

// Wall distance from p to the nearest flow bore, straight from the decoded bores.
double wall(const mold::Layout& layout, const Vec3& p) {
  double best = 1e300;
  for (const auto& b : layout.bores)
    best = std::min(best, geometry::point_segment_distance(p, {b.flow_start, b.flow_end}) - b.diameter / 2);
  return best;
}

// A feasible U in the z = 25 plane, beside the cavity at x = 15 and x = 105.
mold::Genome beside() {
  mold::Circuit c;
  c.diameter = 8;
  c.waypoints = {{15, 0, 25}, {15, 105, 25}, {105, 105, 25}, {105, 0, 25}};
  return {{c}};
}

}  // namespace

TEST_CASE("the worst-covered search finds the sample farthest from every flow bore", "[run][reach]") {
  const mold::MoldSpec spec = trough_spec();
  const mold::Scene scene(spec);
  const mold::Layout layout = mold::decode(scene, beside());
  const std::vector<Vec3> samples{{20, 50, 25}, {60, 60, 40}, {60, 20, 25}};
  const eval::WorstSample w = eval::WorstCoveredSearch(samples, scene.block_bounds().min).find(layout);
  REQUIRE(w.any);
  // (60, 60, 40): 45 mm in x and 15 in z from the leg at x = 15, z = 25; the others are nearer.
  CHECK(w.point == Vec3(60, 60, 40));
  CHECK(w.wall_distance == Approx(std::sqrt(45.0 * 45 + 15 * 15) - 4).epsilon(1e-12));
  CHECK_FALSE(eval::WorstCoveredSearch({}, scene.block_bounds().min).find(layout).any);
}

TEST_CASE("the worst-covered search picks the plain loop's sample and distance on the mold problem's layouts",
          "[run][reach]") {
  // The search screens in single precision and re-scores the nearly worst in double; the
  // reference is the plain loop over every sample and bore (wall above), first of equals.
  // Samples on a coarse grid around bores at integer places give exact ties, which must resolve
  // to the earliest. (More cases: tests/eval/worst_covered_test.cpp.)
  const mold::MoldSpec spec = trough_spec();
  const mold::Scene scene(spec);
  const run::Session session(MTCS_SOURCE_DIR + "/molds/plate_wall_distance.yaml");
  const run::MoldProblem problem(session.pipeline(), {}, session.config().mutation);
  const std::vector<Vec3> samples = eval::thermal_samples(session.scene()).points;
  std::vector<Vec3> grid;
  for (int x = 0; x <= 120; x += 10)
    for (int y = 0; y <= 120; y += 10) grid.emplace_back(x, y, 25);
  opt::Rng rng(3);
  for (int i = 0; i < 40; ++i) {
    const mold::Layout layout = mold::decode(session.scene(), problem.genome(problem.sample(rng)));
    const mold::Layout trough = mold::decode(scene, i % 2 ? beside() : mold::Genome{});
    const std::vector<Vec3>& grid_points = grid;
    for (const auto& [points, l] : {std::pair{&samples, &layout}, std::pair{&grid_points, &trough}}) {
      eval::WorstSample plain;
      for (const Vec3& p : *points) {
        // No bores: every sample at infinity (wall's 1e300 is only its start).
        const double e = l->bores.empty() ? std::numeric_limits<double>::infinity() : wall(*l, p);
        if (!plain.any || e > plain.wall_distance) plain = {p, e, true};
      }
      const eval::WorstSample w = eval::WorstCoveredSearch(*points, l == &layout ? session.scene().block_bounds().min
                                                                                  : scene.block_bounds().min)
                                      .find(*l);
      REQUIRE(w.any);
      CHECK(w.point == plain.point);
      CHECK(w.wall_distance == plain.wall_distance);  // bit for bit: the same distances, min and max
    }
  }
}

TEST_CASE("circuit_reaching lays a feasible circuit in the 1 mm band over the trough", "[run][reach]") {
  const mold::MoldSpec spec = trough_spec();
  const mold::Scene scene(spec);
  const eval::Pipeline pipeline(scene);
  const Vec3 target(60, 60, 40);
  const geometry::Box block = scene.block_bounds();
  auto repair = [&](mold::Circuit& c) {
    for (Vec3& p : c.waypoints) p = p.cwiseMax(block.min).cwiseMin(block.max);
    c.waypoints.front().y() = 0, c.waypoints.back().y() = 0;  // ports on -y
  };
  int found = 0;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    opt::Rng rng(seed);
    const run::ReachRequest request{target, 20, 8, 24, block};
    const run::Reached reached = run::circuit_reaching(pipeline, request, repair, rng);
    CHECK(reached.evaluations >= 1);
    CHECK(reached.evaluations <= request.evaluations);
    const auto& c = reached.circuit;
    if (!c) continue;
    ++found;
    const mold::Genome g{{*c}};
    const eval::Evaluation e = pipeline.evaluate(g);
    CHECK(e.feasible());
    const mold::Layout layout = mold::decode(scene, g);
    const double reach = wall(layout, target);
    CHECK(reach < 20);
    // Above the trough the only place: the band, clear of the sprue.
    CHECK(c->waypoints.front().z() >= 52 - 1e-9);
    CHECK(c->waypoints.front().z() <= 53 + 1e-9);
  }
  // Laid by construction, not by chance: half the seeds or more find the band within 24 evaluations.
  CHECK(found >= 4);
}

TEST_CASE("the reach move gives feasible children nearer the parent's worst sample, the same for the same seed",
          "[run][reach]") {
  const mold::MoldSpec spec = trough_spec();
  const mold::Scene scene(spec);
  const eval::Pipeline pipeline(scene);
  const std::vector<Vec3> samples = eval::thermal_samples(scene).points;
  const eval::WorstSample worst =
      eval::WorstCoveredSearch(samples, scene.block_bounds().min).find(mold::decode(scene, beside()));
  // Children of one feasible parent that are feasible and nearer its worst sample (on the cavity's
  // bottom, reachable only from the side), out of 12,
  // with the reach move on every child (when it finds no circuit, the other moves run) or never.
  auto nearer_children = [&](double reach) {
    run::MutationRates rates;
    rates.insert = rates.remove = rates.snap = rates.diameter = rates.circuit = 0;
    rates.reach = reach;
    const run::MoldProblem problem(pipeline, {}, rates);
    const opt::Genotype parent = problem.encode(beside());
    REQUIRE(problem.evaluate(parent).feasible);
    int n = 0;
    for (std::uint64_t seed = 1; seed <= 12; ++seed) {
      opt::Genotype a = parent, b = parent;
      opt::Rng ra(seed), rb(seed);
      problem.mutate(a, problem.initial_steps(a), ra);
      problem.mutate(b, problem.initial_steps(b), rb);
      CHECK(a == b);
      const mold::Layout child = mold::decode(scene, problem.genome(a));
      if (wall(child, worst.point) < worst.wall_distance - 1e-9 && problem.evaluate(a).feasible) ++n;
    }
    return n;
  };
  const int with = nearer_children(1), without = nearer_children(0);
  INFO("with " << with << " without " << without << " worst " << worst.point.transpose() << " e " << worst.wall_distance);
  CHECK(with >= 4);
  CHECK(with > without);
}

TEST_CASE("an ES run whose moves spend evaluations ends within its budget", "[run][reach][budget]") {
  const mold::MoldSpec spec = trough_spec();
  const mold::Scene scene(spec);
  const eval::Pipeline pipeline(scene);
  run::MutationRates rates;
  rates.reach = 1;  // every offspring tries the reach move first: up to 25 evaluations each
  const run::MoldProblem problem(pipeline, {}, rates);
  long spent_by_moves = 0;
  for (const long budget : {37L, 50L, 61L, 80L}) {
    opt::EsConfig config;
    config.mu = 2, config.lambda = 4, config.evaluations = budget, config.seed = std::uint64_t(budget);
    const opt::EvolutionStrategy es(problem, config);
    long generations = 0;
    const opt::Generation last = opt::run(es, nullptr, [&](const opt::Generation&) { ++generations; });
    INFO("budget " << budget << " generations " << generations);
    CHECK(last.evaluations <= budget);
    CHECK(last.evaluations + config.lambda > budget);  // and not short of it: no room for another generation
    spent_by_moves += last.evaluations - config.mu - config.lambda * (generations - 1);
  }
  CHECK(spent_by_moves > 0);  // the moves did spend: the budget had them to hold
  // SMS-EMOA, steady state and with lambda offspring per step.
  for (const int lambda : {1, 4}) {
    opt::SmsConfig config;
    config.mu = 3, config.lambda = lambda, config.evaluations = 45, config.seed = std::uint64_t(lambda);
    config.ref = {1e6, 1e6, 1e9};  // behind every layout: uniformity, worst_covered (mm), cost
    const opt::SmsEmoa sms(problem, config);
    opt::Generation g = sms.initial();
    while (!sms.done(g)) g = sms.step(g);
    INFO("SMS-EMOA lambda " << lambda);
    CHECK(g.evaluations <= config.evaluations);
  }
}
