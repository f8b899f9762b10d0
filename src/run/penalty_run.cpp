#include "mtcs/run/penalty_run.h"

#include <chrono>

#include "mtcs/opt/hypervolume.h"
#include "mtcs/opt/sms_emoa.h"

namespace mtcs::run {

PenaltyRun run_with_penalty(const Session& session, RunConfig config, std::uint64_t seed,
                            const std::vector<double>& scaled_ref, const std::function<void(int)>& on_decile) {
  config.es.seed = seed;
  // A problem per run: its counters of evaluated and feasible layouts start at 0.
  const MoldProblem problem(session.pipeline(), config.weights, config.mutation, config.penalty);
  const MoldOptimizer optimizer(problem, session.scene(), config);
  const long budget = config.es.evaluations;
  PenaltyRun r;
  r.variant = mold::to_string(problem.penalty_variant());
  r.seed = seed;
  Window open;
  auto close_window = [&](long at) {
    open.to = at;
    open.evaluated = problem.evaluated() - r.evaluations;
    open.feasible = problem.feasible_evaluated() - r.feasible;
    r.evaluations = problem.evaluated();
    r.feasible = problem.feasible_evaluated();
    r.windows.push_back(open);
    open = Window{at, at, 0, 0};
    on_decile(int(r.windows.size()));
  };
  auto decile_end = [&](std::size_t d) { return (budget * long(d + 1) + kDeciles - 1) / kDeciles; };
  const auto t0 = std::chrono::steady_clock::now();
  const opt::Generation last = optimizer.run(nullptr, [&](const opt::Generation& g) {
    while (r.windows.size() < kDeciles && g.evaluations >= decile_end(r.windows.size())) close_window(g.evaluations);
  });
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  while (r.windows.size() < kDeciles) close_window(last.evaluations);  // a budget the last generation fell short of
  std::vector<opt::Point> front = opt::SmsEmoa::front(last);
  const auto& obj = session.spec().objectives;
  for (auto& p : front)
    for (std::size_t k = 0; k < p.size(); ++k) p[k] /= obj.scale(obj.use[k]);
  r.front_size = front.size();
  r.hypervolume = opt::hypervolume(front, scaled_ref);
  return r;
}

}  // namespace mtcs::run
