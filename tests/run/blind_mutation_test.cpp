// The optimiser's baffles and bubblers (issue 42, item 5): the genotype carries each circuit's
// kind (older genotypes read as drilled), and the mutations add, move and remove blind bores
// while every one stays drillable: two waypoints, the entry on a face of drilling.baffles, the
// tip straight below it, their number within drilling.baffles.max and the drilled circuits'
// within circuits.min and max.

#include <catch2/catch.hpp>
#include <set>

#include "mtcs/eval/pipeline.h"
#include "mtcs/mold/decoder.h"
#include "mtcs/run/mold_problem.h"
#include "support/bundled_variant.h"

using namespace mtcs;

namespace {

// The plate with the wall-distance objectives (no thermal model to build: the operators alone).
const mold::MoldSpec& spec() {
  static const mold::MoldSpec s = mold::load_mold_spec(mtcs_test::bundled_variant(
      "plate_wall_distance", "  allowed_faces: [+x, -x, +y, -y]\n",
      "  allowed_faces: [+x, -x, +y, -y]\n  baffles: {faces: [-z], max: 3}\n"));
  return s;
}

}  // namespace

TEST_CASE("blind mutation: the genotype keeps each circuit's kind, and an older genotype reads as drilled", "[run][baffle]") {
  const mold::Scene scene(spec());
  const eval::Pipeline pipeline(scene);
  const run::MoldProblem problem(pipeline, {}, {});
  mold::Genome g;
  g.circuits.push_back({{{70, 0, 80}, {70, 150, 80}, {230, 150, 80}, {230, 0, 80}}, 10});
  g.circuits.push_back({{{150, 100, 0}, {150, 100, 90}}, 8, mold::CircuitKind::Baffle});
  g.circuits.push_back({{{110, 60, 0}, {110, 60, 90}}, 6, mold::CircuitKind::Bubbler});
  const opt::Genotype x = problem.encode(g);
  // [K, slot, n, ...]: the slot is the diameter's index (6, 8, 10) plus 100 x the kind.
  CHECK(x[1] == 2);
  CHECK(x[2 + 1 + 12] == 101);
  CHECK(x[2 + 1 + 12 + 2 + 6] == 200);
  const mold::Genome back = problem.genome(x);
  REQUIRE(back.circuits.size() == 3);
  for (std::size_t c = 0; c < 3; ++c) {
    CHECK(back.circuits[c].kind == g.circuits[c].kind);
    CHECK(back.circuits[c].diameter == g.circuits[c].diameter);
    CHECK(back.circuits[c].waypoints == g.circuits[c].waypoints);
  }
  // A genotype written before kinds: diameter index 1, a straight circuit.
  const opt::Genotype old{1, 1, 2, 70, 0, 80, 70, 200, 80};
  CHECK(problem.genome(old).circuits.at(0).kind == mold::CircuitKind::Drilled);
  CHECK(problem.genome(old).circuits.at(0).diameter == 8);
}

TEST_CASE("blind mutation: offspring add, move and remove baffles and bubblers, every one drillable", "[run][baffle]") {
  const mold::Scene scene(spec());
  const eval::Pipeline pipeline(scene);
  const run::MoldProblem problem(pipeline, {}, {});
  opt::Rng rng(7);
  int most = 0, added = 0, removed = 0, deepened = 0, moved_across = 0;
  std::set<mold::CircuitKind> kinds;
  for (int trial = 0; trial < 40; ++trial) {
    opt::Genotype x = problem.sample(rng);
    for (int step = 0; step < 60; ++step) {
      const mold::Genome before = problem.genome(x);
      const opt::Genotype y = trial % 2 ? problem.recombine(x, problem.sample(rng), rng) : x;
      opt::Genotype child = y;
      problem.mutate(child, problem.initial_steps(child), rng);
      const mold::Genome g = problem.genome(child);
      int blind = 0;
      for (const mold::Circuit& c : g.circuits) {
        if (!is_blind(c.kind)) {
          CHECK(c.waypoints.size() >= 2);
          continue;
        }
        ++blind;
        kinds.insert(c.kind);
        REQUIRE(c.waypoints.size() == 2);
        const geometry::Vec3 &entry = c.waypoints[0], &tip = c.waypoints[1];
        CHECK(entry.z() == 0);
        CHECK(tip.x() == entry.x());
        CHECK(tip.y() == entry.y());
        CHECK(tip.z() >= c.diameter);
        CHECK(tip.z() < 120);
        CHECK(mold::routed_waypoints(scene, c) == c.waypoints);  // already on its drilled axis
      }
      const int drilled = int(g.circuits.size()) - blind;
      CHECK(blind <= 3);
      CHECK(drilled >= spec().circuits.min);
      CHECK(drilled <= spec().circuits.max);
      most = std::max(most, blind);
      int blind_before = 0;
      for (const mold::Circuit& c : before.circuits) blind_before += is_blind(c.kind) ? 1 : 0;
      if (trial % 2 == 0) {
        added += blind > blind_before ? 1 : 0;
        removed += blind < blind_before ? 1 : 0;
        if (blind == blind_before && blind > 0 && g.circuits.size() == before.circuits.size())
          for (std::size_t c = 0; c < g.circuits.size(); ++c) {
            if (!is_blind(g.circuits[c].kind) || g.circuits[c].kind != before.circuits[c].kind) continue;
            deepened += g.circuits[c].waypoints[1].z() != before.circuits[c].waypoints[1].z() ? 1 : 0;
            moved_across += g.circuits[c].waypoints[0].x() != before.circuits[c].waypoints[0].x() ? 1 : 0;
          }
      }
      x = child;
    }
  }
  CHECK(most >= 2);
  CHECK(kinds.size() == 2);
  CHECK(added > 5);
  CHECK(removed > 5);
  CHECK(deepened > 20);
  CHECK(moved_across > 20);
}
