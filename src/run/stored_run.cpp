#include "mtcs/run/stored_run.h"

#include <algorithm>
#include <chrono>

namespace mtcs::run {

std::size_t best_rank(const opt::Generation& g, const opt::Problem& problem) {
  const auto best = std::min_element(g.population.begin(), g.population.end(),
                                     [&](const opt::Individual& a, const opt::Individual& b) { return problem.better(a.score, b.score); });
  return std::size_t(best - g.population.begin());
}

StoredRun run_stored(const MoldOptimizer& optimizer, const MoldProblem& problem, store::RunStore& db,
                     const std::function<void(const opt::Generation&, double, long)>& on_stored,
                     const std::function<bool()>& stop) {
  const bool pareto = optimizer.pareto();
  const auto previous = db.last();
  const double seconds_before = previous ? db.summaries().back().seconds : 0;
  const long evals_before = previous ? previous->evaluations : 0;
  const auto t0 = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
  StoredRun r;
  r.last = optimizer.run(previous ? &*previous : nullptr, [&](const opt::Generation& g) {
    // SMS-EMOA steps one offspring at a time: store (and report) every mu steps.
    if (pareto && g.index % optimizer.mu() != 0) return;
    const double s = elapsed();
    db.save(g, seconds_before + s);
    if (on_stored) on_stored(g, s, g.evaluations - evals_before);
  }, stop);
  if (pareto) {
    if (r.last.index % optimizer.mu() != 0) db.save(r.last, seconds_before + elapsed());  // the last steps
    std::stable_sort(r.last.population.begin(), r.last.population.end(),
                     [&](const opt::Individual& a, const opt::Individual& b) { return problem.better(a.score, b.score); });
  }
  db.commit();  // before the outputs: what they are written from is in the store
  r.interrupted = !optimizer.done(r.last);
  r.seconds = seconds_before + elapsed();
  return r;
}

}  // namespace mtcs::run
