// The ES's restart on stall (issue 14). On a plateau (the sphere flattened to 0 inside the unit
// ball), the best stops improving as soon as a member is inside, so the restart must fire every
// restart_after generations; it is seen from outside: the restart's fresh members cost mu - 1
// evaluations at exactly those generations, the steps restart puts every member back at its
// initial step sizes, and the best is never lost. A run resumed from any generation, or run on
// 2 threads, repeats the uninterrupted run bit for bit (the stall count is in the Generation).

#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <tbb/global_control.h>

#include "mtcs/opt/evolution_strategy.h"
#include "opt/test_functions.h"

using namespace mtcs::opt;

namespace {

// A test function seen through one change (the rest forwards to it).
class Forwarding : public Problem {
 public:
  explicit Forwarding(const Problem& f) : f_(f) {}
  std::string name() const override { return "forwarding " + f_.name(); }
  Genotype sample(Rng& rng) const override { return f_.sample(rng); }
  std::vector<double> initial_steps(const Genotype& g) const override { return f_.initial_steps(g); }
  long mutate(Genotype& g, const std::vector<double>& steps, Rng& rng) const override { return f_.mutate(g, steps, rng); }
  Score evaluate(const Genotype& g) const override { return f_.evaluate(g); }

 private:
  const Problem& f_;
};

// Flat at 0 inside the unit ball.
class Plateau final : public Forwarding {
 public:
  using Forwarding::Forwarding;
  Score evaluate(const Genotype& g) const override {
    Score s = Forwarding::evaluate(g);
    s.value = std::max(0.0, s.value - 1);
    return s;
  }
};

EsConfig restarting(EsConfig::Restart mode, long evaluations = 4000) {
  EsConfig c;
  c.evaluations = evaluations;
  c.seed = 3;
  c.restart_after = 5;
  c.restart = mode;
  return c;
}

std::vector<Generation> all_generations(const EvolutionStrategy& es, const Generation* start = nullptr) {
  std::vector<Generation> seen;
  if (start) seen.push_back(*start);
  run(es, start, [&](const Generation& g) { seen.push_back(g); });
  return seen;
}

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

bool same_generation(const Generation& a, const Generation& b) {
  if (a.index != b.index || a.evaluations != b.evaluations || a.stalled != b.stalled ||
      a.population.size() != b.population.size())
    return false;
  for (std::size_t i = 0; i < a.population.size(); ++i) {
    const auto &x = a.population[i], &y = b.population[i];
    if (!same_bits(x.x, y.x) || !same_bits(x.steps, y.steps) || !same_bits({x.score.value}, {y.score.value})) return false;
  }
  return true;
}

}  // namespace

TEST_CASE("ES restart: on a plateau a population restart fires every restart_after stalled generations, the best kept",
          "[opt][es][restart]") {
  const auto sphere = make_test_function("sphere", 2);
  const Plateau plateau(*sphere);
  const EsConfig c = restarting(EsConfig::Restart::population);
  const EvolutionStrategy es(plateau, c);
  const auto gens = all_generations(es);
  REQUIRE(gens.back().population.front().score.value == 0);  // on the plateau
  int restarts = 0, fresh_after_converged = 0;
  for (std::size_t k = 0; k + 1 < gens.size(); ++k) {
    const Generation &g = gens[k], &next = gens[k + 1];
    INFO("generation " << next.index);
    const bool restart = g.stalled > 0 && g.stalled % c.restart_after == 0;
    restarts += restart ? 1 : 0;
    // The sphere's mutations evaluate nothing: lambda offspring, and mu - 1 fresh members at a restart.
    CHECK(next.evaluations - g.evaluations == c.lambda + (restart ? c.mu - 1 : 0));
    CHECK(next.population.front().score.value <= g.population.front().score.value);  // elitist
    if (g.population.front().score.value == 0) CHECK(next.stalled == g.stalled + 1);  // nothing beats 0
    // A converged population (all on the plateau) has members off it after a restart: fresh ones.
    const auto off = [](const Generation& x) {
      return std::count_if(x.population.begin(), x.population.end(), [](const Individual& i) { return i.score.value > 0; });
    };
    if (restart && off(g) == 0 && off(next) > 0) ++fresh_after_converged;
  }
  CHECK(restarts >= 10);
  CHECK(fresh_after_converged >= 1);
}

TEST_CASE("ES restart: a steps restart puts every member back at its initial step sizes", "[opt][es][restart]") {
  const auto sphere = make_test_function("sphere", 2);
  const Plateau plateau(*sphere);
  const EsConfig c = restarting(EsConfig::Restart::steps);
  const EvolutionStrategy es(plateau, c);
  const auto gens = all_generations(es);
  int restarts = 0, adapted_before = 0;
  for (std::size_t k = 0; k + 1 < gens.size(); ++k) {
    const Generation &g = gens[k], &next = gens[k + 1];
    if (!(g.stalled > 0 && g.stalled % c.restart_after == 0)) continue;
    ++restarts;
    CHECK(next.evaluations - g.evaluations == c.lambda);  // no fresh members
    for (const auto& ind : g.population) adapted_before += ind.steps != plateau.initial_steps(ind.x) ? 1 : 0;
    // On the plateau the offspring only tie with their parents, and ties keep the parents first:
    // the members that stay are the restarted parents.
    for (const auto& ind : next.population)
      for (const auto& parent : g.population)
        if (same_bits(parent.x, ind.x)) CHECK(ind.steps == plateau.initial_steps(ind.x));
  }
  CHECK(restarts >= 10);
  CHECK(adapted_before > 0);  // the check above is no tautology: steps had moved
}

TEST_CASE("ES restart: resumed from any generation, or on 2 threads, the run repeats bit for bit",
          "[opt][es][restart][determinism]") {
  const auto ellipsoid = make_test_function("ellipsoid", 4);
  const Plateau plateau(*ellipsoid);
  for (const auto mode : {EsConfig::Restart::population, EsConfig::Restart::steps}) {
    const EvolutionStrategy es(plateau, restarting(mode, 3000));
    const auto full = [&] {
      const tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
      return all_generations(es);
    }();
    REQUIRE(std::any_of(full.begin(), full.end(), [&](const Generation& g) { return es.restarts_after(g); }));
    for (std::size_t from = 0; from + 1 < full.size(); from += 3) {
      INFO("resumed from generation " << from);
      const auto resumed = all_generations(es, &full[from]);
      REQUIRE(resumed.size() == full.size() - from);
      for (std::size_t k = 0; k < resumed.size(); ++k) CHECK(same_generation(resumed[k], full[from + k]));
    }
    const tbb::global_control two(tbb::global_control::max_allowed_parallelism, 2);
    const auto threaded = all_generations(es);
    REQUIRE(threaded.size() == full.size());
    for (std::size_t k = 0; k < full.size(); ++k) CHECK(same_generation(threaded[k], full[k]));
  }
}

TEST_CASE("ES restart: off (restart_after 0) the stall is counted and nothing restarts", "[opt][es][restart]") {
  const auto sphere = make_test_function("sphere", 2);
  const Plateau plateau(*sphere);
  EsConfig c = restarting(EsConfig::Restart::population);
  c.restart_after = 0;
  const auto gens = all_generations(EvolutionStrategy(plateau, c));
  REQUIRE(gens.back().stalled > 20);
  for (std::size_t k = 0; k + 1 < gens.size(); ++k) CHECK(gens[k + 1].evaluations - gens[k].evaluations == c.lambda);
}

namespace {

// Offspring are their parents' copies: whatever enters a population came from a parent, so a
// resting best (no parent) can only be seen once.
class Frozen final : public Forwarding {
 public:
  using Forwarding::Forwarding;
  long mutate(Genotype&, const std::vector<double>&, Rng&) const override { return 0; }
};

// The sphere lifted to 1000: every gain is below the restart's 0.1 % tolerance, so the ES
// stalls and restarts while its members still improve a little.
class Lifted final : public Forwarding {
 public:
  using Forwarding::Forwarding;
  Score evaluate(const Genotype& g) const override {
    Score s = Forwarding::evaluate(g);
    s.value = 1000 + 1e-3 * s.value;
    return s;
  }
};

}  // namespace

TEST_CASE("ES restart: while the kept best rests it is no parent, so no copy of it enters the population",
          "[opt][es][restart]") {
  const auto sphere = make_test_function("sphere", 3);
  const Frozen frozen(*sphere);
  EsConfig c = restarting(EsConfig::Restart::population, 3000);
  c.recombination = false;
  const EvolutionStrategy es(frozen, c);
  const auto gens = all_generations(es);
  int resting = 0;
  for (std::size_t k = 0; k + 1 < gens.size(); ++k) {
    if (!es.best_rests(gens[k])) continue;
    ++resting;
    const Genotype& best = gens[k].population.front().x;
    const auto copies = std::count_if(gens[k + 1].population.begin(), gens[k + 1].population.end(),
                                      [&](const Individual& ind) { return same_bits(ind.x, best); });
    INFO("generation " << gens[k].index);
    CHECK(copies == 1);
  }
  CHECK(resting > 20);
}

TEST_CASE("ES restart: the rest ends when the new run leads, even by less than the tolerance", "[opt][es][restart]") {
  const auto sphere = make_test_function("sphere", 2);
  const Lifted lifted(*sphere);
  const EvolutionStrategy es(lifted, restarting(EsConfig::Restart::population, 4000));
  const auto gens = all_generations(es);
  int ended = 0, stalled_on = 0;
  for (std::size_t k = 0; k + 1 < gens.size(); ++k) {
    const Generation &g = gens[k], &next = gens[k + 1];
    const bool leads = next.population.front().score.value < g.population.front().score.value;
    if (es.best_rests(g) && leads) {
      ++ended;
      CHECK(next.stalled == 0);
    }
    if (!es.best_rests(g) && leads) {  // gains under 0.1 % do not count outside a rest
      ++stalled_on;
      CHECK(next.stalled == g.stalled + 1);
    }
  }
  CHECK(ended > 0);
  CHECK(stalled_on > 0);
}

TEST_CASE("ES restart: an island's arrival that leads resets the stall count, others leave it", "[opt][es][restart][islands]") {
  const auto sphere = make_test_function("sphere", 2);
  const EvolutionStrategy es(*sphere, restarting(EsConfig::Restart::population));
  auto member = [&](double x) {
    const Genotype g{x, 0};
    return Individual{g, sphere->initial_steps(g), sphere->evaluate(g)};
  };
  Generation g;
  g.index = 12;
  for (const double x : {1.0, 1.5, 2.0, 2.5}) g.population.push_back(member(x));  // best 1, worst 6.25
  for (const int stalled : {2, 5, 7}) {  // counting; resting (restart_after 5); resting after a restart
    g.stalled = stalled;
    INFO("stalled " << stalled);
    const bool resting = es.best_rests(g);
    // A clear lead (value 0.25 against 1): a gain, so the count starts again and the rest ends.
    const Generation lead = es.immigrate(g, {member(0.5)});
    CHECK(lead.population.front().x[0] == 0.5);
    CHECK(lead.stalled == 0);
    CHECK_FALSE(es.best_rests(lead));
    // A lead under the tolerance (0.1 %): a gain only while the best rests (as in step()).
    const Generation slight = es.immigrate(g, {member(std::sqrt(0.9995))});
    CHECK(slight.population.front().x[0] == std::sqrt(0.9995));
    CHECK(slight.stalled == (resting ? 0 : stalled));
    // No lead: the arrival replaces the worst, the count goes on.
    const Generation behind = es.immigrate(g, {member(1.2)});
    CHECK(behind.population.front().x[0] == 1.0);
    CHECK(behind.population.back().x[0] == 2.0);
    CHECK(behind.stalled == stalled);
  }
}
