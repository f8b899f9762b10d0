#include "mtcs/opt/sms_emoa.h"

#include "sms_fronts.h"

#include <algorithm>
#include <limits>
#include <mutex>
#include <numeric>

namespace mtcs::opt {

struct SmsEmoa::Fronts {
  std::mutex lock;  // one population at a time (a shared algorithm steps under it)
  detail::SteadyStateFronts fronts;
};

SmsEmoa::SmsEmoa(const Problem& problem, SmsConfig config)
    : problem_(problem), config_(std::move(config)), fronts_(std::make_shared<Fronts>()) {}

Generation SmsEmoa::initial() const {
  return sample_population(problem_, config_.seed, config_.mu, config_.start);
}

Generation SmsEmoa::step(const Generation& prev) const {
  Generation next = prev;
  advance(next);
  return next;
}

void SmsEmoa::advance(Generation& g) const {
  ++g.index;
  const int mu = int(g.population.size());
  const long lambda = std::max(1L, std::min<long>(config_.lambda, config_.evaluations - g.evaluations));
  std::vector<Individual> children(static_cast<std::size_t>(lambda));
  long spent_by_moves = 0;  // evaluations the mutations themselves made (the budget counts them)
  for (long k = 0; k < lambda; ++k) {
    Rng rng = Rng::for_individual(config_.seed, std::uint64_t(g.index), std::uint64_t(k));
    const Individual& a = g.population[std::size_t(rng.below(mu))];
    const Individual& b = g.population[std::size_t(rng.below(mu))];
    Individual& child = children[std::size_t(k)];
    child.x = problem_.recombine(a.x, b.x, rng);
    child.steps = a.steps;
    const long may_spend = config_.moves_within_budget ? config_.evaluations - g.evaluations - lambda - spent_by_moves
                                                       : std::numeric_limits<long>::max() / 2;
    spent_by_moves += problem_.mutate_within(child.x, child.steps, rng, may_spend);
  }
  // The reduction drops lambda members and takes the infeasible ones first, the most violated
  // first: while every parent is feasible no child behind them is kept, and the problem may
  // skip what would not change that (an infeasible child's objectives). An infeasible parent
  // as the bar skips nothing.
  const Score& bar = std::max_element(g.population.begin(), g.population.end(), [](const Individual& a, const Individual& b) {
                       return feasible_first(a.score, b.score);
                     })->score;
  if (lambda == 1) {
    children.front().score = problem_.evaluate_unless_behind(children.front().x, bar);
  } else {
    std::vector<Genotype> xs;
    for (const auto& c : children) xs.push_back(c.x);
    std::vector<Score> scores = evaluate_all(problem_, xs, bar);
    for (std::size_t k = 0; k < children.size(); ++k) children[k].score = std::move(scores[k]);
  }
  g.evaluations += lambda + spent_by_moves;

  // Reduce: drop lambda members, one at a time from the worst front, ranked as the problem asks
  // (its penalty method).
  const std::lock_guard<std::mutex> hold(fronts_->lock);
  detail::SteadyStateFronts& fronts = fronts_->fronts;
  if (!fronts.holds(g.population)) {
    fronts.clear();
    for (const auto& ind : g.population) fronts.push(ind.score, problem_.ranking(ind.score));
  }
  for (auto& child : children) {
    fronts.push(child.score, problem_.ranking(child.score));
    g.population.push_back(std::move(child));
  }
  for (long k = 0; k < lambda; ++k) {
    const std::size_t drop = fronts.worst(config_.domcount_then_hv, config_.ref);
    fronts.erase(drop);
    g.population.erase(g.population.begin() + long(drop));
  }
}

std::vector<Individual> SmsEmoa::emigrants(const Generation& g, int k) const {
  std::vector<Score> ranked;
  for (const auto& ind : g.population) ranked.push_back(problem_.ranking(ind.score));
  std::vector<std::size_t> first;
  for (std::size_t i = 0; i < ranked.size(); ++i) {
    bool dominated = false;
    for (std::size_t j = 0; j < ranked.size() && !dominated; ++j)
      dominated = j != i && constrained_dominates(ranked[j], ranked[i]);
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
  // Reduced back to its size one removal at a time, as a step reduces.
  Generation out = g;
  detail::SteadyStateFronts fronts;
  for (const auto& ind : out.population) fronts.push(ind.score, problem_.ranking(ind.score));
  for (const auto& a : arrivals) {
    fronts.push(a.score, problem_.ranking(a.score));
    out.population.push_back(a);
  }
  while (out.population.size() > g.population.size()) {
    const std::size_t drop = fronts.worst(config_.domcount_then_hv, config_.ref);
    fronts.erase(drop);
    out.population.erase(out.population.begin() + long(drop));
  }
  return out;
}

std::vector<Point> SmsEmoa::front(const Generation& g) {
  std::vector<Point> out;
  for (std::size_t i = 0; i < g.population.size(); ++i) {
    const auto& s = g.population[i].score;
    if (!s.feasible) continue;
    bool dominated = false;
    for (std::size_t j = 0; j < g.population.size() && !dominated; ++j)
      dominated = j != i && constrained_dominates(g.population[j].score, s);
    if (!dominated && std::find(out.begin(), out.end(), s.objectives) == out.end()) out.push_back(s.objectives);
  }
  return out;
}

Generation run(const SmsEmoa& algorithm, const Generation* start, const std::function<void(const Generation&)>& on_step,
               const std::function<bool(const Generation&)>& stop) {
  // run_to_budget's loop, stepping in place.
  Generation g = start ? *start : algorithm.initial();
  if (!start && on_step) on_step(g);
  while (!algorithm.done(g) && !(stop && stop(g))) {
    algorithm.advance(g);
    if (on_step) on_step(g);
  }
  return g;
}

}  // namespace mtcs::opt
