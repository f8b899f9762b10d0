// The ES on standard functions, to stated tolerances within stated budgets, and its
// determinism: same seed, same generations, whatever the thread count.

#include <catch2/catch.hpp>
#include <atomic>
#include <tbb/global_control.h>

#include "mtcs/opt/evolution_strategy.h"
#include "mtcs/opt/forwarding_problem.h"
#include "opt/test_functions.h"

using namespace mtcs::opt;

namespace {

double solve(const std::string& name, int n, long budget, std::uint64_t seed, EsConfig c = {},
             bool correlated = false) {
  const auto f = make_test_function(name, n, correlated);
  c.evaluations = budget;
  c.seed = seed;
  const EvolutionStrategy es(*f, c);
  return run(es, nullptr, {}).population.front().score.value;
}

}  // namespace

TEST_CASE("ES: sphere 10-D to 1e-10 within 20 000 evaluations", "[opt][es]") {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) CHECK(solve("sphere", 10, 20000, seed) < 1e-10);
}

TEST_CASE("ES: ellipsoid 10-D, condition 1e6, to 1e-10 within 60 000 evaluations", "[opt][es]") {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) CHECK(solve("ellipsoid", 10, 60000, seed) < 1e-10);
}

TEST_CASE("ES: Rosenbrock 10-D to 1e-8 within 200 000 evaluations", "[opt][es]") {
  // (15 + 100) with correlated mutations: the valley needs rotated steps.
  EsConfig c;
  c.mu = 15, c.lambda = 100;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) CHECK(solve("rosenbrock", 10, 200000, seed, c, true) < 1e-8);
}

TEST_CASE("ES: same seed, same generations, with 1 thread or 2", "[opt][es][determinism]") {
  const auto f = make_test_function("rosenbrock", 6, true);
  EsConfig c;
  c.evaluations = 3000;
  c.seed = 42;
  const EvolutionStrategy es(*f, c);
  auto record = [&](int threads) {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
    std::vector<std::vector<double>> log;
    run(es, nullptr, [&](const Generation& g) {
      for (const auto& ind : g.population) {
        log.push_back(ind.x);
        log.push_back(ind.steps);
      }
    });
    return log;
  };
  CHECK(record(1) == record(2));
}

TEST_CASE("ES: resuming from a stored generation ends where the uninterrupted run ends", "[opt][es]") {
  const auto f = make_test_function("ellipsoid", 5);
  EsConfig c;
  c.evaluations = 4000;
  const EvolutionStrategy es(*f, c);
  std::vector<Generation> seen;
  const Generation full = run(es, nullptr, [&](const Generation& g) { seen.push_back(g); });
  const Generation resumed = run(es, &seen[seen.size() / 2], {});
  CHECK(resumed.index == full.index);
  CHECK(resumed.population.front().x == full.population.front().x);
  CHECK(resumed.population.front().score.value == full.population.front().score.value);
}

namespace {

// A test function whose screen is a stand-in for a cheaper tier: the function itself, or its
// negation (a screen that ranks backwards). Counts the calls of each.
class Screened final : public ForwardingProblem {
 public:
  Screened(const Problem& f, bool backwards) : ForwardingProblem(f), backwards_(backwards) {}
  Score evaluate(const Genotype& g) const override {
    ++evaluated;
    return inner_.evaluate(g);
  }
  Score screen(const Genotype& g) const override {
    ++screened;
    Score s = inner_.evaluate(g);
    if (backwards_) s.value = -s.value;
    return s;
  }
  mutable std::atomic<long> evaluated{0}, screened{0};

 private:
  bool backwards_;
};

}  // namespace

TEST_CASE("ES multi-fidelity: with a faithful screen, survivors >= mu give the same generations for fewer evaluations",
          "[opt][es][fidelity]") {
  // (mu + lambda) keeps at most mu offspring, and the screen ranks them as evaluate does: the
  // best mu offspring are all that can enter, so screening changes the cost, not the run.
  const auto f = make_test_function("sphere", 5);
  EsConfig c;
  c.evaluations = 2010;
  c.seed = 7;
  const EvolutionStrategy plain(*f, c);
  c.survivors = c.mu;
  const Screened screened(*f, false);
  const EvolutionStrategy multi(screened, c);
  std::vector<std::vector<double>> a, b;
  const Generation end_a = run(plain, nullptr, [&](const Generation& g) {
    for (const auto& i : g.population) a.push_back(i.x);
  });
  const Generation end_b = run(multi, nullptr, [&](const Generation& g) {
    for (const auto& i : g.population) b.push_back(i.x);
  });
  CHECK(a == b);
  CHECK(end_a.evaluations == end_b.evaluations);
  const long generations = end_b.index;
  CHECK(generations == 50);
  CHECK(screened.screened == generations * c.lambda);
  CHECK(screened.evaluated == c.mu + generations * c.survivors);
}

TEST_CASE("ES multi-fidelity: only the screen's best survive, and the population holds evaluate's scores",
          "[opt][es][fidelity]") {
  // A backwards screen lets only the worst offspring through: the run must do worse than the
  // faithful one, and every stored score is still the true one.
  const auto f = make_test_function("sphere", 5);
  EsConfig c;
  c.evaluations = 2010;
  c.seed = 3;
  c.survivors = 5;
  const Screened faithful(*f, false), backwards(*f, true);
  const Generation good = run(EvolutionStrategy(faithful, c), nullptr, {});
  const Generation bad = run(EvolutionStrategy(backwards, c), nullptr, [&](const Generation& g) {
    for (const auto& i : g.population) CHECK(i.score.value == f->evaluate(i.x).value);
  });
  CHECK(good.population.front().score.value < 1e-3 * bad.population.front().score.value);
  CHECK(backwards.evaluated == c.mu + bad.index * c.survivors);
}

namespace {

// A test function whose mutation scores two candidates of its own before it moves, as the mold
// problem's reach move does: what it spends is in the ES's count, so it shortens the run.
class SearchingMutation final : public Problem {
 public:
  explicit SearchingMutation(const Problem& f) : f_(f) {}
  std::string name() const override { return f_.name(); }
  Genotype sample(Rng& rng) const override { return f_.sample(rng); }
  std::vector<double> initial_steps(const Genotype& g) const override { return f_.initial_steps(g); }
  long mutate(Genotype& g, const std::vector<double>& steps, Rng& rng) const override {
    f_.mutate(g, steps, rng);
    return 2;
  }
  Score evaluate(const Genotype& g) const override { return f_.evaluate(g); }

 private:
  const Problem& f_;
};

}  // namespace

TEST_CASE("ES: the evaluations a mutation spends count in the budget", "[opt][es][budget]") {
  const auto f = make_test_function("sphere", 5);
  EsConfig c;
  c.evaluations = 2010;
  const SearchingMutation searching(*f);
  std::vector<long> counts;
  const Generation end = run(EvolutionStrategy(searching, c), nullptr,
                             [&](const Generation& g) { counts.push_back(g.evaluations); });
  REQUIRE(counts.size() > 2);
  for (std::size_t k = 1; k < counts.size(); ++k) CHECK(counts[k] - counts[k - 1] == 3 * c.lambda);
  CHECK(end.evaluations >= c.evaluations);
  CHECK(end.evaluations < c.evaluations + 3 * c.lambda);
}

TEST_CASE("ES: a given start is member 0 of the first generation, the rest are the plain run's samples",
          "[opt][es][start]") {
  const auto f = make_test_function("rosenbrock", 6, false);
  const Genotype optimum(6, 1.0);  // Rosenbrock's minimum, 0 there
  EsConfig c;
  c.evaluations = 600;
  c.seed = 5;
  const Generation plain = sample_population(*f, c.seed, c.mu);
  const Generation given = sample_population(*f, c.seed, c.mu, {optimum});
  REQUIRE(given.population.size() == plain.population.size());
  CHECK(given.population[0].x == optimum);
  CHECK(given.population[0].score.value == 0.0);
  for (std::size_t i = 1; i < plain.population.size(); ++i) CHECK(given.population[i].x == plain.population[i].x);
  CHECK(given.evaluations == plain.evaluations);

  // Plus selection keeps the exact optimum from generation 0 to the end; the plain run's random
  // samples never reach 0 in 600 evaluations.
  EsConfig started = c;
  started.start = {optimum};
  const Generation end = run(EvolutionStrategy(*f, started), nullptr, {});
  CHECK(end.population.front().score.value == 0.0);
  CHECK(run(EvolutionStrategy(*f, c), nullptr, {}).population.front().score.value > 0.0);
}
