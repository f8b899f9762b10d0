// SMS-EMOA's kept fronts (src/opt/sms_fronts.h) against the full sort they replace: Deb's fast
// non-dominated sorting of all points at every step, then the paper's removal rules, as
// sms_emoa.cpp did it before (copied here as the reference). The same member must go, ties
// included, on random sets built to tie (duplicates, shared coordinates, equal violations,
// points outside the reference box), and whole runs must match step for step.

#include <catch2/catch.hpp>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "mtcs/opt/benchmark_problems.h"
#include "mtcs/opt/sms_emoa.h"
#include "opt/sms_fronts.h"

using namespace mtcs::opt;

namespace {

std::vector<std::size_t> worst_front(const std::vector<Score>& scores, bool* is_first) {
  const std::size_t n = scores.size();
  std::vector<int> count(n, 0);
  std::vector<std::vector<std::size_t>> beats(n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
      if (i != j && constrained_dominates(scores[i], scores[j])) beats[i].push_back(j), ++count[j];
  std::vector<std::size_t> current;
  for (std::size_t i = 0; i < n; ++i)
    if (count[i] == 0) current.push_back(i);
  *is_first = true;
  for (;;) {
    std::vector<std::size_t> next;
    for (const std::size_t i : current)
      for (const std::size_t j : beats[i])
        if (--count[j] == 0) next.push_back(j);
    if (next.empty()) return current;
    current = std::move(next);
    *is_first = false;
  }
}

// The member the full sort removes.
std::size_t reference_drop(const std::vector<Score>& ranked, bool domcount_then_hv, const Point& ref) {
  bool first = false;
  const std::vector<std::size_t> worst = worst_front(ranked, &first);
  std::size_t drop = worst.front();
  if (worst.size() > 1) {
    if (!ranked[worst.front()].feasible) {
      for (const std::size_t i : worst)
        if (ranked[i].violation > ranked[drop].violation) drop = i;
    } else {
      std::vector<int> count(worst.size(), 0);
      if (domcount_then_hv && !first)
        for (std::size_t w = 0; w < worst.size(); ++w)
          for (const auto& other : ranked) count[w] += constrained_dominates(other, ranked[worst[w]]) ? 1 : 0;
      const int most = *std::max_element(count.begin(), count.end());
      std::vector<std::size_t> tied;
      for (std::size_t w = 0; w < worst.size(); ++w)
        if (count[w] == most) tied.push_back(w);
      std::size_t w = tied.front();
      if (tied.size() > 1) {
        std::vector<Point> pts;
        for (const std::size_t i : worst) pts.push_back(ranked[i].objectives);
        const std::vector<double> c = contributions(pts, ref);
        for (const std::size_t t : tied)
          if (c[t] < c[w]) w = t;
      }
      drop = worst[w];
    }
  }
  return drop;
}

// The old step, whole: the reference run.
Generation reference_step(const Problem& problem, const SmsConfig& config, const Generation& prev) {
  Generation next = prev;
  next.index = prev.index + 1;
  Rng rng = Rng::for_individual(config.seed, std::uint64_t(next.index), 0);
  const int mu = int(prev.population.size());
  const Individual& a = prev.population[std::size_t(rng.below(mu))];
  const Individual& b = prev.population[std::size_t(rng.below(mu))];
  Individual child;
  child.x = problem.recombine(a.x, b.x, rng);
  child.steps = a.steps;
  problem.mutate(child.x, child.steps, rng);
  child.score = problem.evaluate(child.x);
  next.population.push_back(std::move(child));
  ++next.evaluations;
  std::vector<Score> ranked;
  for (const auto& ind : next.population) ranked.push_back(problem.ranking(ind.score));
  next.population.erase(next.population.begin() + long(reference_drop(ranked, config.domcount_then_hv, config.ref)));
  return next;
}

// Points made to tie: coordinates on a coarse grid (shared values, duplicates, mutual
// non-domination in bulk), some outside the reference box, some infeasible with few violation
// levels, some infinite.
Score random_score(std::mt19937_64& gen, std::size_t m, int grid) {
  std::uniform_int_distribution<int> cell(0, grid);
  std::uniform_real_distribution<double> u(0, 1);
  Score s;
  for (std::size_t k = 0; k < m; ++k) s.objectives.push_back(double(cell(gen)) / grid * 1.2);
  const double r = u(gen);
  if (r < 0.1) {
    s.feasible = false;
    s.violation = double(cell(gen) % 4 + 1);
  } else if (r < 0.13) {
    s.objectives[0] = std::numeric_limits<double>::infinity();
  } else if (r < 0.4 && m == 2) {
    // on a line: many mutually non-dominated points
    const double t = double(cell(gen)) / grid;
    s.objectives = {t, 1 - t};
  }
  return s;
}

}  // namespace

TEST_CASE("SMS fronts: the kept fronts drop what the full sort drops", "[opt][sms-emoa][fronts]") {
  std::mt19937_64 gen(12345);
  for (const std::size_t m : {2u, 3u}) {
    for (const int grid : {4, 12, 1000}) {
      for (const bool domcount : {true, false}) {
        for (const int lambda : {1, 3}) {
          const Point ref(m, 1.1);
          std::vector<Score> pop;
          detail::SteadyStateFronts fronts;
          for (int i = 0; i < 30; ++i) {
            pop.push_back(random_score(gen, m, grid));
            fronts.push(pop.back(), pop.back());
          }
          int checked = 0;
          for (int step = 0; step < 300; ++step) {
            for (int k = 0; k < lambda; ++k) {
              pop.push_back(random_score(gen, m, grid));
              fronts.push(pop.back(), pop.back());
            }
            for (int k = 0; k < lambda; ++k) {
              const std::size_t expected = reference_drop(pop, domcount, ref);
              const std::size_t got = fronts.worst(domcount, ref);
              checked += expected == got ? 1 : 0;
              REQUIRE(got == expected);
              pop.erase(pop.begin() + long(expected));
              fronts.erase(got);
            }
          }
          CHECK(checked == 300 * lambda);
        }
      }
    }
  }
}

TEST_CASE("SMS fronts: a run steps exactly as the full sort did", "[opt][sms-emoa][fronts]") {
  for (const std::string name : {"zdt1", "zdt3", "dtlz1", "dtlz2"}) {
    const auto p = make_benchmark_problem(name);
    SmsConfig c;
    c.mu = 30;
    c.seed = 4;
    c.evaluations = 2500;
    c.ref = std::vector<double>(std::size_t(objective_count(name)), 1.1);
    const SmsEmoa sms(*p, c);
    Generation ours = sms.initial(), theirs = ours;
    while (!sms.done(ours)) {
      sms.advance(ours);
      theirs = reference_step(*p, c, theirs);
      REQUIRE(ours.population.size() == theirs.population.size());
      for (std::size_t i = 0; i < ours.population.size(); ++i) REQUIRE(ours.population[i].x == theirs.population[i].x);
    }
    CHECK(ours.evaluations == theirs.evaluations);
    // step() on a copy agrees with advance() too (the fronts follow whichever population comes).
    CHECK(sms.step(theirs).population.back().x == [&] { Generation g = theirs; sms.advance(g); return g.population.back().x; }());
  }
}

TEST_CASE("SMS-EMOA with lambda offspring per step: same result whatever the thread count", "[opt][sms-emoa][fronts]") {
  const auto p = make_benchmark_problem("zdt2");
  SmsConfig c;
  c.mu = 20;
  c.lambda = 8;
  c.evaluations = 1000;
  c.ref = {1.1, 1.1};
  const SmsEmoa sms(*p, c);
  const auto with_threads = [&](int threads) {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
    return run(sms, nullptr, {});
  };
  const Generation a = with_threads(1);
  CHECK(a.evaluations == 1000);
  CHECK(a.index == (1000 - 20) / 8 + 1);  // the last step spends the 4 left
  CHECK(a.population.size() == 20);
  const Generation b = with_threads(2);
  for (std::size_t i = 0; i < a.population.size(); ++i) CHECK(a.population[i].x == b.population[i].x);
}

namespace {

// Mutually non-dominated 3-D points in bulk (on the unit sphere's octant), some on a coarse grid
// of angles (shared coordinates, duplicates), a few dominated ones, outside the box or infinite.
Score front_score(std::mt19937_64& gen, int grid) {
  std::uniform_real_distribution<double> u(0, 1);
  const auto angle = [&] { return grid > 0 ? double(std::uniform_int_distribution<int>(0, grid)(gen)) / grid : u(gen); };
  const double a = angle() * 1.5707963267948966, b = angle() * 1.5707963267948966;
  Score s;
  s.objectives = {std::cos(a) * std::cos(b), std::cos(a) * std::sin(b), std::sin(a)};
  const double r = u(gen);
  if (r < 0.08) for (auto& v : s.objectives) v *= 1.05;  // behind the front
  else if (r < 0.1) s.objectives[1] = 1.15;              // outside the box
  else if (r < 0.11) s.objectives[2] = std::numeric_limits<double>::infinity();
  return s;
}

}  // namespace

TEST_CASE("SMS fronts: the kept 3-D contributions drop what the full sort drops", "[opt][sms-emoa][fronts]") {
  std::mt19937_64 gen(777);
  const Point ref(3, 1.1);
  for (const int grid : {0, 6, 40}) {
    for (const int lambda : {1, 3}) {
      std::vector<Score> pop;
      detail::SteadyStateFronts fronts;
      for (int i = 0; i < 40; ++i) {
        pop.push_back(front_score(gen, grid));
        fronts.push(pop.back(), pop.back());
      }
      for (int step = 0; step < 400; ++step) {
        for (int k = 0; k < lambda; ++k) {
          pop.push_back(front_score(gen, grid));
          fronts.push(pop.back(), pop.back());
        }
        for (int k = 0; k < lambda; ++k) {
          const std::size_t expected = reference_drop(pop, true, ref);
          const std::size_t got = fronts.worst(true, ref);
          REQUIRE(got == expected);
          pop.erase(pop.begin() + long(expected));
          fronts.erase(got);
        }
      }
      // The kept path decided most removals (ties on the grids go to the full sweep).
      CHECK(fronts.kept_picks() > (grid == 6 ? 50 : 200));
      CHECK(fronts.kept().recomputed() > 0);
    }
  }
}

TEST_CASE("SMS fronts: kept 3-D contributions equal the full computation's within rounding", "[opt][sms-emoa][fronts]") {
  std::mt19937_64 gen(99);
  const Point ref(3, 1.1);
  std::vector<Score> pop;
  detail::SteadyStateFronts fronts;
  for (int i = 0; i < 60; ++i) {
    pop.push_back(front_score(gen, 0));
    fronts.push(pop.back(), pop.back());
  }
  for (int step = 0; step < 200; ++step) {
    pop.push_back(front_score(gen, 0));
    fronts.push(pop.back(), pop.back());
    const std::size_t drop = fronts.worst(true, ref);
    pop.erase(pop.begin() + long(drop));
    fronts.erase(drop);
    if (!fronts.kept().valid()) continue;
    // The first front's contributions by the general routine, member by member.
    std::vector<std::size_t> first;
    for (std::size_t i = 0; i < pop.size(); ++i) {
      bool dominated = false;
      for (std::size_t j = 0; j < pop.size() && !dominated; ++j)
        dominated = j != i && constrained_dominates(pop[j], pop[i]);
      if (!dominated) first.push_back(i);
    }
    std::vector<Point> pts;
    for (const std::size_t i : first) pts.push_back(pop[i].objectives);
    const std::vector<double> c = contributions(pts, ref);
    for (std::size_t k = 0; k < first.size(); ++k)
      REQUIRE(fronts.kept().value(first[k]) == Approx(c[k]).epsilon(1e-12).margin(1e-300));
  }
  CHECK(fronts.kept().valid());
}
