// The ES on standard functions, to stated tolerances within stated budgets, and its
// determinism: same seed, same generations, whatever the thread count.

#include <catch2/catch.hpp>
#include <tbb/global_control.h>

#include "mtcs/opt/evolution_strategy.h"
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
