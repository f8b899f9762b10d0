// The stages keep each bore's (and bore pair's, and circuit's) results by exact geometry
// (src/eval/exact_cache.h): a child evaluated right after its parent reuses the parent's
// unchanged bores. That must change nothing: for every mutation operator, the child's
// evaluation through a pipeline that has just scored the parent equals, bit for bit, its
// evaluation through a second pipeline that has never seen the parent.

#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>

#include "eval/surface_samples.h"
#include "eval/tiled_samples.h"
#include "mtcs/eval/pipeline.h"
#include "mtcs/mold/decoder.h"
#include "mtcs/opt/rng.h"
#include "mtcs/run/session.h"
#include "support/plain_nearest_squared.h"
#include "support/paths.h"
#include "support/bundled_variant.h"

using namespace mtcs;

namespace {

void require_identical(const eval::Evaluation& a, const eval::Evaluation& b) {
  REQUIRE(a.objectives == b.objectives);
  REQUIRE(a.violation == b.violation);
  REQUIRE(a.violations.size() == b.violations.size());
  for (std::size_t i = 0; i < a.violations.size(); ++i) {
    const auto &x = a.violations[i], &y = b.violations[i];
    CHECK(x.kind == y.kind);
    CHECK(x.elements == y.elements);
    CHECK(x.distance == y.distance);
    CHECK(x.margin == y.margin);
    CHECK(x.amount == y.amount);
    CHECK(x.where == y.where);
    CHECK(x.closest == y.closest);
  }
}

// Bores of `child` whose hole is exactly one of `parent`'s.
int shared_bores(const mold::Layout& parent, const mold::Layout& child) {
  int n = 0;
  for (const auto& c : child.bores)
    for (const auto& p : parent.bores)
      if (c.hole.p0 == p.hole.p0 && c.hole.p1 == p.hole.p1 && c.hole.radius == p.hole.radius) {
        ++n;
        break;
      }
  return n;
}

}  // namespace

TEST_CASE("A child scored after its parent equals a cold score, for every mutation operator", "[run][incremental]") {
  const std::string mold = GENERATE(std::string("plate_wall_distance"), std::string("gear"));
  const run::Session session(mtcs_test::wall_distance_spec(mold));
  const mold::Scene& scene = session.scene();
  const eval::Pipeline warm(scene), cold(scene);
  struct Operator {
    const char* name;
    run::MutationRates rates;
  };
  // Each structural operator alone, with one hole moved (not all): what it changes is all that changes.
  const run::MutationRates none{.insert = 0, .remove = 0, .snap = 0, .diameter = 0, .circuit = 0, .moves = 1};
  auto with = [&](auto field, double rate) {
    run::MutationRates r = none;
    r.*field = rate;
    return r;
  };
  const std::vector<Operator> operators{
      {"insert", with(&run::MutationRates::insert, 1)},   {"remove", with(&run::MutationRates::remove, 1)},
      {"snap", with(&run::MutationRates::snap, 1)},       {"diameter", with(&run::MutationRates::diameter, 1)},
      {"circuit", with(&run::MutationRates::circuit, 1)}, {"every hole moves", with(&run::MutationRates::moves, 0)},
      {"two holes move", with(&run::MutationRates::moves, 2)}, {"the run's rates", session.config().mutation}};
  int shared = 0;
  for (const auto& op : operators) {
    SECTION(std::string(op.name)) {
      const run::MoldProblem problem(session.pipeline(), {}, op.rates);
      opt::Rng rng(7);
      for (int i = 0; i < 12; ++i) {
        const opt::Genotype parent = problem.sample(rng);
        opt::Genotype child = parent;
        problem.mutate(child, problem.initial_steps(child), rng);
        const mold::Layout p = mold::decode(scene, problem.genome(parent)), c = mold::decode(scene, problem.genome(child));
        warm.evaluate(p);
        INFO(mold << ", " << op.name << ", child " << i);
        require_identical(warm.evaluate(c), cold.evaluate(c));
        shared += shared_bores(p, c);
      }
      // The operators that keep bores do exercise the cached path.
      if (op.rates.moves > 0) CHECK(shared > 0);
    }
  }
}

// The same with physics objectives (molds/plate.yaml: T2d line sinks): the line-sink cache keeps
// the blocks of several layouts, so a child scored after other parents' children still reuses its
// parent's bores; its score must equal a cold one bit for bit.
TEST_CASE("A child scored after other parents' children equals a cold score with physics objectives", "[run][incremental]") {
  const run::Session session(MTCS_SOURCE_DIR + "/molds/plate.yaml");
  const mold::Scene& scene = session.scene();
  const eval::Pipeline& warm = session.pipeline();
  const eval::Pipeline cold(scene);
  const run::MoldProblem problem(warm, {}, session.config().mutation);
  opt::Rng rng(11);
  std::vector<opt::Genotype> parents;
  for (int i = 0; i < 3; ++i) {
    parents.push_back(problem.sample(rng));
    warm.evaluate(mold::decode(scene, problem.genome(parents.back())));
  }
  int shared = 0;
  for (int i = 0; i < 6; ++i) {  // children of the parents in turn: the last layout is never the parent
    const opt::Genotype& parent = parents[std::size_t(i % 3)];
    opt::Genotype child = parent;
    problem.mutate(child, problem.initial_steps(child), rng);
    const mold::Layout p = mold::decode(scene, problem.genome(parent)), c = mold::decode(scene, problem.genome(child));
    INFO("child " << i);
    const eval::Evaluation a = warm.evaluate(c), b = cold.evaluate(c);
    require_identical(a, b);
    shared += shared_bores(p, c);
  }
  CHECK(shared > 0);
}

// The thermal stage minimises a circuit's distances over tiles of samples and skips far bores
// (src/eval/tiled_samples.h): its objectives must be, bit for bit, those of the plain loop over
// every bore and every sample it stands for, for random layouts and for children.
TEST_CASE("The thermal objectives equal the plain loop's bit for bit", "[run][incremental]") {
  // Per sample the plain loop's e and target; the weighted sum in the order the stage documents
  // (by slot of the tiled samples, in eight lanes), and within 1e-13 of the sum in samples'
  // order. 400 layouts: the stage's circuit cache starts over several times, some in the
  // middle of a layout; the last layout has 70 circuits (more than one layout's share of the
  // stage's rows).
  const std::string mold = GENERATE(std::string("plate_wall_distance"), std::string("gear"));
  const run::Session session(mtcs_test::wall_distance_spec(mold));
  const mold::Scene& scene = session.scene();
  const auto& use = scene.spec().objectives.use;
  const auto slot = [&](mold::Objective o) { return std::size_t(std::find(use.begin(), use.end(), o) - use.begin()); };
  REQUIRE(slot(mold::Objective::Uniformity) < use.size());
  REQUIRE(slot(mold::Objective::WorstCovered) < use.size());
  const eval::SurfaceSamples s = eval::sample_cavity(*scene.spec().cavity);
  const geometry::Vec3 origin = scene.block_bounds().min;
  const eval::TiledSamples tiles(s, origin);
  const mold::Length& target_at = scene.spec().objectives.target_wall_distance;
  // Per sample the nearest circuit's sqrt(min squared distance) - r, the earlier circuit on ties.
  struct Plain {
    double uniformity, worst, uniformity_in_sample_order;
  };
  auto plain = [&](const mold::Layout& layout) {
    std::vector<double> best(s.size(), scene.block_bounds().size().norm()), target(s.size(), target_at.at(0));
    for (std::size_t b = 0; b < layout.bores.size();) {
      const std::size_t first = b;
      while (b < layout.bores.size() && layout.bores[b].circuit == layout.bores[first].circuit) ++b;
      std::vector<eval::FlowSegment> segments;
      for (std::size_t k = first; k < b; ++k) segments.push_back({layout.bores[k].flow_start, layout.bores[k].flow_end});
      const double r = layout.bores[first].diameter / 2;
      const std::vector<float> m = mtcs_test::plain_nearest_squared(s, origin, segments);
      for (std::size_t i = 0; i < s.size(); ++i) {
        const double e = double(std::sqrt(m[i])) - r;  // the root in single precision, as m
        if (e < best[i]) best[i] = e, target[i] = target_at.at(2 * r);
      }
    }
    double sum = 0;
    std::vector<double> lanes(8, 0.0), by_slot(tiles.slots(), 0.0);
    for (std::size_t i = 0; i < s.size(); ++i) {
      const double dev = best[i] - target[i];
      sum += s.weight[i] * dev * dev;
      by_slot[tiles.slot(i)] = s.weight[i] * dev * dev;
    }
    for (std::size_t k = 0; k < by_slot.size(); ++k) lanes[k % 8] += by_slot[k];
    double lane_sum = 0;
    for (const double l : lanes) lane_sum += l;
    return Plain{std::sqrt(lane_sum / s.total_weight()), *std::max_element(best.begin(), best.end()),
                 std::sqrt(sum / s.total_weight())};
  };
  const run::MoldProblem problem(session.pipeline(), {}, session.config().mutation);
  opt::Rng rng(5);
  // Parents, their children (hits on the parent's circuits) and parents seen a while ago (hits
  // on older rows of the stage's cache), as a run mixes them.
  std::vector<mold::Genome> seen;
  for (int i = 0; i < 400; ++i) {
    mold::Genome genome;
    if (i % 3 == 0 || seen.size() < 8) {
      genome = problem.genome(problem.sample(rng));
    } else if (i % 3 == 1) {
      opt::Genotype g = problem.encode(seen.back());
      problem.mutate(g, problem.initial_steps(g), rng);
      genome = problem.genome(g);
    } else {
      genome = seen[seen.size() - 1 - std::size_t(rng.below(8))];
    }
    seen.push_back(genome);
    if (i == 399) {  // 70 more circuits, each its own geometry
      const std::size_t n = genome.circuits.size();
      for (int c = 0; c < 70; ++c) {
        mold::Circuit k = genome.circuits[std::size_t(c) % n];
        for (auto& p : k.waypoints) p.z() -= 0.01 * (c + 1);
        genome.circuits.push_back(k);
      }
    }
    const mold::Layout layout = mold::decode(scene, genome);
    const auto e = session.pipeline().evaluate(layout);
    const Plain want = plain(layout);
    INFO(mold << ", layout " << i);
    CHECK(e.objectives[slot(mold::Objective::Uniformity)] == want.uniformity);
    CHECK(e.objectives[slot(mold::Objective::Uniformity)] ==
          Approx(want.uniformity_in_sample_order).epsilon(1e-13));
    CHECK(e.objectives[slot(mold::Objective::WorstCovered)] == want.worst);
  }
}
