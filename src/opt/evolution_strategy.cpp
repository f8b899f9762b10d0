#include "mtcs/opt/evolution_strategy.h"
#include "mtcs/opt/migration.h"

#include "run_to_budget.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <numeric>

namespace mtcs::opt {

Genotype Problem::recombine(const Genotype& a, const Genotype&, Rng&) const { return a; }

EvolutionStrategy::EvolutionStrategy(const Problem& problem, EsConfig config)
    : problem_(problem), config_(config) {}

namespace {

// Best first; ties keep their order (stable), so the result does not depend on threads.
void sort_population(const Problem& problem, std::vector<Individual>& pop) {
  std::stable_sort(pop.begin(), pop.end(),
                   [&](const Individual& a, const Individual& b) { return problem.better(a.score, b.score); });
}

const Individual& worst_of(const Problem& problem, const std::vector<Individual>& pop) {
  return *std::max_element(pop.begin(), pop.end(),
                           [&](const Individual& a, const Individual& b) { return problem.better(a.score, b.score); });
}

}  // namespace

Generation EvolutionStrategy::initial() const {
  Generation g = sample_population(problem_, config_.seed, config_.mu, config_.start);
  sort_population(problem_, g.population);
  return g;
}

std::vector<Individual> EvolutionStrategy::screened(std::vector<Individual>& offspring,
                                                    const std::vector<Genotype>& xs, const Score* bar) const {
  const auto rough = bar ? screen_all(problem_, xs, *bar) : screen_all(problem_, xs);
  std::vector<std::size_t> order(offspring.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return problem_.better(rough[a], rough[b]); });
  order.resize(std::size_t(config_.survivors));
  std::sort(order.begin(), order.end());  // sampling order, so that ties keep it
  std::vector<Genotype> best;
  for (const std::size_t i : order) best.push_back(xs[i]);
  const auto scores = bar ? evaluate_all(problem_, best, *bar) : evaluate_all(problem_, best);
  std::vector<Individual> kept;
  for (std::size_t k = 0; k < order.size(); ++k) {
    kept.push_back(std::move(offspring[order[k]]));
    kept.back().score = scores[k];
  }
  return kept;
}

std::vector<Individual> EvolutionStrategy::restarted(const Generation& prev, long& evaluations) const {
  std::vector<Individual> pop = prev.population;
  if (!restarts_after(prev) || pop.empty()) return pop;
  if (config_.restart == EsConfig::Restart::steps) {
    for (auto& ind : pop) ind.steps = problem_.initial_steps(ind.x);
    return pop;
  }
  // Fresh samples from generators the offspring never use (index lambda and up).
  std::vector<Genotype> xs;
  for (std::size_t i = 1; i < pop.size(); ++i) {
    Rng rng = Rng::for_individual(config_.seed, std::uint64_t(prev.index + 1), std::uint64_t(config_.lambda) + i);
    xs.push_back(problem_.sample(rng));
  }
  const auto scores = evaluate_all(problem_, xs);
  evaluations += long(xs.size());
  for (std::size_t i = 1; i < pop.size(); ++i) pop[i] = {xs[i - 1], problem_.initial_steps(xs[i - 1]), scores[i - 1]};
  return pop;
}

bool EvolutionStrategy::improved(const Generation& next, const Generation& prev) const {
  if (next.population.empty() || prev.population.empty()) return false;
  const Score& a = next.population.front().score;
  const Score& b = prev.population.front().score;
  if (!problem_.better(a, b)) return false;
  // While the kept best rests, any lead of the new run ends the rest: the member that leads is
  // then the one a restart would keep, and the converged best must not rest in its place.
  if (best_rests(prev)) return true;
  const bool same_standing = a.feasible == b.feasible && a.violation == b.violation;
  return !same_standing || b.value - a.value > config_.restart_tolerance * std::abs(b.value);
}

Generation EvolutionStrategy::immigrate(const Generation& g, const std::vector<Individual>& arrivals) const {
  Generation out = replace_worst(problem_, g, arrivals);
  if (improved(out, g)) out.stalled = 0;
  return out;
}

Generation EvolutionStrategy::step(const Generation& prev_generation) const {
  long spent_by_restart = 0;
  Generation prev;  // prev_generation, or its restart
  prev.index = prev_generation.index;
  prev.population = restarted(prev_generation, spent_by_restart);
  // Parents are drawn from prev.population[first_parent...]: the best rests in a restart's run.
  const int first_parent = best_rests(prev_generation) ? 1 : 0;
  const int mu = int(prev.population.size()) - first_parent;
  const int lambda = config_.lambda;
  std::vector<Individual> offspring(static_cast<std::size_t>(lambda));
  std::vector<Genotype> xs(static_cast<std::size_t>(lambda));
  long spent_by_moves = 0;  // evaluations the mutations themselves made (the budget counts them)
  // What the budget holds for this generation: lambda offspring, and the moves' spending.
  const long left = config_.moves_within_budget ? config_.evaluations - prev_generation.evaluations - spent_by_restart
                                                : std::numeric_limits<long>::max() / 2;
  for (int i = 0; i < lambda; ++i) {
    Rng rng = Rng::for_individual(config_.seed, std::uint64_t(prev.index + 1), std::uint64_t(i));
    if (config_.random_search) {
      Individual fresh;
      fresh.x = problem_.sample(rng);
      fresh.steps = problem_.initial_steps(fresh.x);
      xs[std::size_t(i)] = fresh.x;
      offspring[std::size_t(i)] = std::move(fresh);
      continue;
    }
    const Individual* parents = prev.population.data() + first_parent;
    const Individual& a = parents[rng.below(mu)];
    const Individual* b = &a;
    if (config_.recombination && config_.rho >= 2 && mu > 1) {
      int j = rng.below(mu - 1);
      b = &parents[j >= int(&a - parents) ? j + 1 : j];
    }
    Individual child;
    child.x = b == &a ? a.x : problem_.recombine(a.x, b->x, rng);
    // Strategy parameters: the parents' mean where they match the child (geometric for step
    // sizes, arithmetic for angles), then log-normal steps and additive angles.
    const std::size_t na = problem_.rotation_angles(child.x);
    const std::size_t n = problem_.step_sizes(child.x);
    const auto fresh = problem_.initial_steps(child.x);
    child.steps = a.steps.size() == fresh.size() ? a.steps : fresh;
    if (b != &a && b->steps.size() == fresh.size()) {
      for (std::size_t k = 0; k < n; ++k) child.steps[k] = std::sqrt(child.steps[k] * b->steps[k]);
      for (std::size_t k = n; k < n + na; ++k) child.steps[k] = (child.steps[k] + b->steps[k]) / 2;
    }
    // Learning rates (Schwefel): from the number of parameters the steps act on.
    const double dim = double(std::max<std::size_t>(1, problem_.dimension(child.x)));
    const double tau0 = 1 / std::sqrt(2.0 * dim), tau = 1 / std::sqrt(2 * std::sqrt(dim));
    const double global = tau0 * rng.normal();
    for (std::size_t k = 0; k < n; ++k)
      child.steps[k] = std::clamp(child.steps[k] * std::exp(global + (n > 1 ? tau * rng.normal() : 0.0)),
                                  config_.min_step, config_.max_step);
    constexpr double kBeta = 0.0873, kPi = 3.14159265358979323846;
    for (std::size_t k = n; k < n + na; ++k) {
      double angle = child.steps[k] + kBeta * rng.normal();
      if (angle > kPi) angle -= 2 * kPi;
      if (angle < -kPi) angle += 2 * kPi;
      child.steps[k] = angle;
    }
    spent_by_moves += problem_.mutate_within(child.x, child.steps, rng, left - lambda - spent_by_moves);
    xs[std::size_t(i)] = child.x;
    offspring[std::size_t(i)] = std::move(child);
  }
  // With mu parents in the pool, an offspring behind the worst of them is not kept: the
  // problem may skip what would not change that (an infeasible child's objectives).
  const bool has_bar = config_.plus && int(prev.population.size()) >= config_.mu && !prev.population.empty();
  const Score bar = has_bar ? worst_of(problem_, prev.population).score : Score{};
  if (config_.survivors > 0 && config_.survivors < lambda) {
    offspring = screened(offspring, xs, has_bar ? &bar : nullptr);
  } else {
    const auto scores = has_bar ? evaluate_all(problem_, xs, bar) : evaluate_all(problem_, xs);
    for (int i = 0; i < lambda; ++i) offspring[std::size_t(i)].score = scores[std::size_t(i)];
  }

  Generation next;
  next.index = prev.index + 1;
  next.evaluations = prev_generation.evaluations + spent_by_restart + lambda + spent_by_moves;
  std::vector<Individual> pool = config_.plus ? prev.population : std::vector<Individual>{};
  // Moved, not copied (genotypes, steps, violation texts): the offspring are not used below.
  pool.insert(pool.end(), std::make_move_iterator(offspring.begin()),
              std::make_move_iterator(offspring.end()));
  sort_population(problem_, pool);
  pool.resize(std::min<std::size_t>(pool.size(), std::size_t(config_.mu)));
  next.population = std::move(pool);
  next.stalled = improved(next, prev_generation) ? 0 : prev_generation.stalled + 1;
  return next;
}

Generation run(const EvolutionStrategy& es, const Generation* start,
               const std::function<void(const Generation&)>& on_generation,
               const std::function<bool(const Generation&)>& stop) {
  return run_to_budget(es, start, on_generation, stop);
}

}  // namespace mtcs::opt
