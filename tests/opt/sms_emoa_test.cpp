// SMS-EMOA on ZDT problems against pagmo's NSGA-II, run here on the same budgets and seeds
// (mu = 100, 20 000 evaluations, reference (1.1, 1.1); the best 100 points can reach 0.8721 on
// ZDT1), and its determinism.

#include <catch2/catch.hpp>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "bench/pagmo_peer.h"
#include "mtcs/opt/benchmark_problems.h"
#include "mtcs/opt/sms_emoa.h"

using namespace mtcs::opt;

namespace {

double final_hv(const std::string& name, std::uint64_t seed, long evaluations = 20000) {
  const auto p = make_benchmark_problem(name);
  SmsConfig c;
  c.seed = seed;
  c.evaluations = evaluations;
  c.ref = std::vector<double>(std::size_t(objective_count(name)), 1.1);
  const SmsEmoa sms(*p, c);
  return hypervolume(SmsEmoa::front(run(sms, nullptr, {})), c.ref);
}

// pagmo's NSGA-II (Deb's settings, population 100) on pagmo's own ZDT: the hypervolume of its
// final population's non-dominated points.
double nsga2_hv(const std::string& name, unsigned seed, long evaluations = 20000) {
  const std::vector<double> ref(2, 1.1);
  std::vector<std::vector<double>> f = mtcs::bench::pagmo_run(name, "nsga2", evaluations, seed), front;
  for (const auto& a : f)
    if (std::none_of(f.begin(), f.end(), [&](const auto& b) { return b != a && b[0] <= a[0] && b[1] <= a[1]; }))
      front.push_back(a);
  return hypervolume(front, ref);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

TEST_CASE("SMS-EMOA beats pagmo's NSGA-II's hypervolume on ZDT1 and ZDT2, same seeds and budget", "[opt][sms-emoa]") {
  for (const std::string name : {"zdt1", "zdt2"}) {
    std::vector<double> ours, theirs;
    for (unsigned seed = 1; seed <= 5; ++seed) ours.push_back(final_hv(name, seed)), theirs.push_back(nsga2_hv(name, seed));
    INFO(name << ": SMS-EMOA median " << median(ours) << ", NSGA-II median " << median(theirs));
    CHECK(median(ours) > median(theirs));
    CHECK(*std::min_element(ours.begin(), ours.end()) > 0.5);  // every run converged to the front
    if (name == "zdt1") CHECK(*std::max_element(ours.begin(), ours.end()) <= 0.8721 + 1e-6);  // the optimal 100 points
  }
}

TEST_CASE("SMS-EMOA: same seed, same front", "[opt][sms-emoa][determinism]") {
  CHECK(final_hv("zdt3", 5, 3000) == final_hv("zdt3", 5, 3000));
}

TEST_CASE("SMS-EMOA: same seed, same populations, with 1 thread or 2", "[opt][sms-emoa][determinism]") {
  // Two and three objectives: the 2-D and the 3-D contribution code both select.
  for (const std::string name : {"zdt1", "dtlz2"}) {
    const auto p = make_benchmark_problem(name);
    SmsConfig c;
    c.mu = 20;
    c.seed = 9;
    c.evaluations = 800;
    c.ref = std::vector<double>(std::size_t(objective_count(name)), 1.1);
    const SmsEmoa sms(*p, c);
    auto record = [&](int threads) {
      const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
      std::vector<std::vector<double>> log;
      run(sms, nullptr, [&](const Generation& g) {
        for (const auto& ind : g.population) {
          log.push_back(ind.x);
          log.push_back(ind.score.objectives);
        }
      });
      return log;
    };
    const auto one = record(1);
    CHECK(one.size() > 2 * 20 * 700);  // every step was recorded
    CHECK(one == record(2));
  }
}

TEST_CASE("benchmark problems: known points", "[opt][sms-emoa]") {
  // ZDT1 at x = 0: f = (0, 1); DTLZ2 with the distance variables at 0.5 lies on the unit sphere.
  const auto zdt1 = make_benchmark_problem("zdt1");
  const auto s = zdt1->evaluate(Genotype(30, 0.0));
  CHECK(s.objectives == std::vector<double>{0, 1});
  const auto dtlz2 = make_benchmark_problem("dtlz2");
  Genotype x(12, 0.5);
  x[0] = 0.3, x[1] = 0.8;
  const auto f = dtlz2->evaluate(x).objectives;
  CHECK(f[0] * f[0] + f[1] * f[1] + f[2] * f[2] == Approx(1.0));
  CHECK_THROWS_AS(make_benchmark_problem("zdt5"), std::invalid_argument);
}

namespace {

// ZDT1 with a constraint x0 <= 0.5, ranked as a death penalty does: an infeasible point's
// objectives are infinite (worse than any feasible point, equal to every infeasible one).
class DeathRankedZdt1 final : public Problem {
 public:
  DeathRankedZdt1() : zdt1_(make_benchmark_problem("zdt1")) {}
  std::string name() const override { return "zdt1-death"; }
  Genotype sample(Rng& rng) const override { return zdt1_->sample(rng); }
  std::vector<double> initial_steps(const Genotype& g) const override { return zdt1_->initial_steps(g); }
  long mutate(Genotype& g, const std::vector<double>& s, Rng& rng) const override { return zdt1_->mutate(g, s, rng); }
  Genotype recombine(const Genotype& a, const Genotype& b, Rng& rng) const override { return zdt1_->recombine(a, b, rng); }
  Score evaluate(const Genotype& g) const override {
    Score s = zdt1_->evaluate(g);
    s.violation = std::max(0.0, g[0] - 0.5);
    s.feasible = s.violation == 0;
    return s;
  }
  Score ranking(const Score& s) const override {
    if (s.feasible) return s;
    Score r = s;
    for (double& v : r.objectives) v = std::numeric_limits<double>::infinity();
    r.feasible = true, r.violation = 0;
    return r;
  }

 private:
  std::unique_ptr<Problem> zdt1_;
};

}  // namespace

TEST_CASE("SMS-EMOA ranks by the problem's ranking: a death penalty's infinite objectives", "[opt][sms-emoa]") {
  const DeathRankedZdt1 p;
  SmsConfig c;
  c.mu = 20;
  c.evaluations = 3000;
  c.ref = {1.1, 1.1};
  const Generation last = run(SmsEmoa(p, c), nullptr, {});
  // Infinite points contribute nothing and lose to every feasible point: none survives.
  for (const auto& ind : last.population) CHECK(ind.score.feasible);
  const auto front = SmsEmoa::front(last);
  REQUIRE(front.size() > 1);
  for (const auto& f : front) CHECK(f[0] <= 0.5);
  const double hv = hypervolume(front, c.ref);
  CHECK(std::isfinite(hv));
  CHECK(hv > 0.3);
}

TEST_CASE("SMS-EMOA: the evaluations a mutation spends count in the budget", "[opt][sms-emoa][budget]") {
  // ZDT1 whose mutation scores one candidate of its own first, as the mold problem's reach move does.
  class Searching final : public Problem {
   public:
    Searching() : zdt1_(make_benchmark_problem("zdt1")) {}
    std::string name() const override { return "zdt1-searching"; }
    Genotype sample(Rng& rng) const override { return zdt1_->sample(rng); }
    std::vector<double> initial_steps(const Genotype& g) const override { return zdt1_->initial_steps(g); }
    long mutate(Genotype& g, const std::vector<double>& s, Rng& rng) const override { return 1 + zdt1_->mutate(g, s, rng); }
    Score evaluate(const Genotype& g) const override { return zdt1_->evaluate(g); }

   private:
    std::unique_ptr<Problem> zdt1_;
  } searching;
  SmsConfig c;
  c.mu = 20;
  c.evaluations = 400;
  c.ref = {1.1, 1.1};
  std::vector<long> counts;
  run(SmsEmoa(searching, c), nullptr, [&](const Generation& g) { counts.push_back(g.evaluations); });
  REQUIRE(counts.size() > 2);
  for (std::size_t k = 1; k < counts.size(); ++k) CHECK(counts[k] - counts[k - 1] == 2);
  CHECK(counts.back() >= c.evaluations);
  CHECK(counts.size() < 200);  // half the steps of a mutation that spends nothing
}

TEST_CASE("SmsEmoa::front: each non-dominated point once, the dominated and infeasible left out", "[opt][sms]") {
  // A converged ES population holds one layout many times: replay listed it five times.
  Generation g;
  for (const auto& [objectives, feasible] : std::vector<std::pair<Point, bool>>{
           {{1, 3}, true}, {{2, 2}, true}, {{1, 3}, true}, {{1, 3}, true}, {{3, 3}, true}, {{0, 0}, false}, {{2, 2}, true}}) {
    Individual ind;
    ind.score.objectives = objectives;
    ind.score.feasible = feasible;
    ind.score.violation = feasible ? 0 : 1;
    g.population.push_back(ind);
  }
  CHECK(SmsEmoa::front(g) == std::vector<Point>{{1, 3}, {2, 2}});
  CHECK(hypervolume(SmsEmoa::front(g), {4, 4}) == Approx(3 * 1 + 2 * 1));  // (4-1)(4-3) + (4-2)(3-2)
}

TEST_CASE("SMS-EMOA: a given start opens the initial population, the other members are the plain run's", "[opt][sms-emoa][start]") {
  const auto p = make_benchmark_problem("zdt1");
  SmsConfig c;
  c.seed = 3;
  c.mu = 20;
  c.ref = {1.1, 1.1};
  const Generation plain = SmsEmoa(*p, c).initial();
  // ZDT1's front is g = 1: x1 in [0, 1], every other variable 0; f = (x1, 1 - sqrt(x1)).
  Genotype on_front(plain.population[0].x.size(), 0.0);
  on_front[0] = 0.25;
  c.start = {on_front};
  const Generation started = SmsEmoa(*p, c).initial();
  REQUIRE(started.population.size() == plain.population.size());
  CHECK(started.population[0].x == on_front);
  CHECK(started.population[0].score.objectives[0] == Approx(0.25).margin(1e-15));
  CHECK(started.population[0].score.objectives[1] == Approx(0.5).margin(1e-15));
  for (std::size_t i = 1; i < plain.population.size(); ++i) CHECK(started.population[i].x == plain.population[i].x);
  // A point on the true front is never dominated: after 400 steps it is still on the front.
  c.evaluations = 400;
  const auto front = SmsEmoa::front(run(SmsEmoa(*p, c), nullptr, {}));
  CHECK(std::find(front.begin(), front.end(), started.population[0].score.objectives) != front.end());
}
