#include "mtcs/opt/sms_emoa.h"

#include "run_to_budget.h"

#include <algorithm>
#include <numeric>

namespace mtcs::opt {
namespace {

// a constrained-dominates b: feasible beats infeasible, less violation beats more, then Pareto.
bool dominates(const Score& a, const Score& b) {
  if (a.feasible != b.feasible) return a.feasible;
  if (!a.feasible) return a.violation < b.violation;
  bool strictly = false;
  for (std::size_t k = 0; k < a.objectives.size(); ++k) {
    if (a.objectives[k] > b.objectives[k]) return false;
    strictly = strictly || a.objectives[k] < b.objectives[k];
  }
  return strictly;
}

// Indices of the worst non-dominated front (fast non-dominated sorting, Deb et al.).
std::vector<std::size_t> worst_front(const std::vector<Score>& scores, bool* is_first) {
  const std::size_t n = scores.size();
  std::vector<int> count(n, 0);
  std::vector<std::vector<std::size_t>> beats(n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
      if (i != j && dominates(scores[i], scores[j])) beats[i].push_back(j), ++count[j];
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

}  // namespace

SmsEmoa::SmsEmoa(const Problem& problem, SmsConfig config) : problem_(problem), config_(std::move(config)) {}

Generation SmsEmoa::initial() const {
  return sample_population(problem_, config_.seed, config_.mu);
}

Generation SmsEmoa::step(const Generation& prev) const {
  Generation next = prev;
  next.index = prev.index + 1;
  Rng rng = Rng::for_individual(config_.seed, std::uint64_t(next.index), 0);
  const int mu = int(prev.population.size());
  const Individual& a = prev.population[std::size_t(rng.below(mu))];
  const Individual& b = prev.population[std::size_t(rng.below(mu))];
  Individual child;
  child.x = problem_.recombine(a.x, b.x, rng);
  child.steps = a.steps;
  problem_.mutate(child.x, child.steps, rng);
  child.score = problem_.evaluate(child.x);
  next.population.push_back(std::move(child));
  ++next.evaluations;

  next.population.erase(next.population.begin() + long(loser(next.population)));
  return next;
}

// The member a step removes: one of the worst front, ranked as the problem asks (its penalty method).
std::size_t SmsEmoa::loser(const std::vector<Individual>& population) const {
  std::vector<Score> ranked;
  ranked.reserve(population.size());
  for (const auto& ind : population) ranked.push_back(problem_.ranking(ind.score));
  bool first = false;
  const std::vector<std::size_t> worst = worst_front(ranked, &first);
  std::size_t drop = worst.front();
  if (worst.size() > 1) {
    const bool feasible = ranked[worst.front()].feasible;
    if (!feasible) {
      // Infeasible front: the largest violation goes.
      for (const std::size_t i : worst)
        if (ranked[i].violation > ranked[drop].violation) drop = i;
    } else {
      // Candidates: the whole worst front, or (paper's rule, fronts after the first) those
      // dominated by the most members; among them the least exclusive hypervolume goes.
      std::vector<int> count(worst.size(), 0);
      if (config_.domcount_then_hv && !first)
        for (std::size_t w = 0; w < worst.size(); ++w)
          for (const auto& other : ranked)
            count[w] += dominates(other, ranked[worst[w]]) ? 1 : 0;
      const int most = *std::max_element(count.begin(), count.end());
      std::vector<std::size_t> tied;
      for (std::size_t w = 0; w < worst.size(); ++w)
        if (count[w] == most) tied.push_back(w);
      std::size_t w = tied.front();
      if (tied.size() > 1) {
        std::vector<Point> pts;
        for (const std::size_t i : worst) pts.push_back(ranked[i].objectives);
        const std::vector<double> c = contributions(pts, config_.ref);
        for (const std::size_t t : tied)
          if (c[t] < c[w]) w = t;
      }
      drop = worst[w];
    }
  }
  return drop;
}

std::vector<Individual> SmsEmoa::emigrants(const Generation& g, int k) const {
  std::vector<Score> ranked;
  for (const auto& ind : g.population) ranked.push_back(problem_.ranking(ind.score));
  std::vector<std::size_t> first;
  for (std::size_t i = 0; i < ranked.size(); ++i) {
    bool dominated = false;
    for (std::size_t j = 0; j < ranked.size() && !dominated; ++j) dominated = j != i && dominates(ranked[j], ranked[i]);
    if (!dominated) first.push_back(i);
  }
  if (!first.empty() && ranked[first.front()].feasible) {  // largest exclusive hypervolume first
    std::vector<Point> pts;
    for (const std::size_t i : first) pts.push_back(ranked[i].objectives);
    const std::vector<double> c = contributions(pts, config_.ref);
    std::vector<std::size_t> order(first.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return c[a] > c[b]; });
    std::vector<std::size_t> sorted;
    for (const std::size_t o : order) sorted.push_back(first[o]);
    first = std::move(sorted);
  }
  first.resize(std::min(first.size(), std::size_t(std::max(k, 0))));
  std::vector<Individual> out;
  for (const std::size_t i : first) out.push_back(g.population[i]);
  return out;
}

Generation SmsEmoa::immigrate(const Generation& g, const std::vector<Individual>& arrivals) const {
  Generation out = g;
  out.population.insert(out.population.end(), arrivals.begin(), arrivals.end());
  while (out.population.size() > g.population.size())
    out.population.erase(out.population.begin() + long(loser(out.population)));
  return out;
}

std::vector<Point> SmsEmoa::front(const Generation& g) {
  std::vector<Point> out;
  for (std::size_t i = 0; i < g.population.size(); ++i) {
    const auto& s = g.population[i].score;
    if (!s.feasible) continue;
    bool dominated = false;
    for (std::size_t j = 0; j < g.population.size() && !dominated; ++j)
      dominated = j != i && dominates(g.population[j].score, s);
    if (!dominated) out.push_back(s.objectives);
  }
  return out;
}

Generation run(const SmsEmoa& algorithm, const Generation* start, const std::function<void(const Generation&)>& on_step,
               const std::function<bool(const Generation&)>& stop) {
  return run_to_budget(algorithm, start, on_step, stop);
}

}  // namespace mtcs::opt
