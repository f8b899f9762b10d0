// The ES and SMS-EMOA score an offspring without its objectives when the mold problem sees it is
// infeasible and every parent feasible (constrained domination: such a child is never kept). The
// run must be the run that scores every child: the same generations bit for bit, each skipped
// child infeasible with the violations a full evaluation gives it, every other child's objectives
// equal.

#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <mutex>

#include "mtcs/opt/evolution_strategy.h"
#include "mtcs/opt/forwarding_problem.h"
#include "mtcs/opt/sms_emoa.h"
#include "mtcs/run/session.h"
#include "support/paths.h"

using namespace mtcs;

namespace {

// The mold problem with every score it gives kept by genotype. `lazy`: it forwards
// evaluate_unless_behind (the skip); otherwise it keeps the default (a full evaluation).
class Scored final : public opt::ForwardingProblem {
 public:
  Scored(const run::MoldProblem& inner, bool lazy) : ForwardingProblem(inner), lazy_(lazy) {}

  opt::Score evaluate(const opt::Genotype& g) const override { return kept(g, inner_.evaluate(g)); }
  opt::Score evaluate_unless_behind(const opt::Genotype& g, const opt::Score& bar) const override {
    return lazy_ ? kept(g, inner_.evaluate_unless_behind(g, bar)) : evaluate(g);
  }

  std::map<opt::Genotype, opt::Score> scores;

 private:
  opt::Score kept(const opt::Genotype& g, opt::Score s) const {
    const std::lock_guard<std::mutex> hold(lock_);
    const_cast<Scored*>(this)->scores[g] = s;
    return s;
  }
  bool lazy_;
  mutable std::mutex lock_;
};

std::vector<opt::Generation> optimised(const std::string& algorithm, const opt::Problem& problem, long evaluations,
                                       std::size_t objectives) {
  std::vector<opt::Generation> seen;
  const auto keep = [&](const opt::Generation& g) { seen.push_back(g); };
  if (algorithm == "es") {
    opt::EsConfig c;
    c.seed = 3;
    c.evaluations = evaluations;
    opt::run(opt::EvolutionStrategy(problem, c), nullptr, keep);
  } else {
    opt::SmsConfig c;
    c.mu = 20;
    c.lambda = algorithm == "sms-emoa" ? 1 : 8;
    c.seed = 3;
    c.evaluations = evaluations;
    c.ref.assign(objectives, 1e9);
    opt::run(opt::SmsEmoa(problem, c), nullptr, keep);
  }
  return seen;
}

bool same(const opt::Score& a, const opt::Score& b) {
  return a.objectives == b.objectives && a.violation == b.violation && a.feasible == b.feasible && a.value == b.value &&
         a.detail == b.detail;
}

}  // namespace

TEST_CASE("ES, SMS-EMOA: infeasible children of feasible parents skip their objectives, the run unchanged",
          "[run][es][sms][skip]") {
  const auto [mold, evaluations] = GENERATE(std::pair<std::string, long>{"plate_wall_distance", 4000},
                                            std::pair<std::string, long>{"plate", 1500});
  const std::string algorithm = GENERATE(std::string("es"), std::string("sms-emoa"), std::string("sms-emoa, lambda 8"));
  INFO(mold << ", " << algorithm);
  const run::Session full_session(MTCS_SOURCE_DIR + "/molds/" + mold + ".yaml"),
      lazy_session(MTCS_SOURCE_DIR + "/molds/" + mold + ".yaml");
  REQUIRE(full_session.problem().penalty_variant() == mold::PenaltyVariant::ConstrainedDomination);
  const Scored full(full_session.problem(), false), lazy(lazy_session.problem(), true);
  const std::size_t m = full_session.spec().objectives.use.size();
  const auto a = optimised(algorithm, full, evaluations, m), b = optimised(algorithm, lazy, evaluations, m);

  REQUIRE(a.size() == b.size());
  REQUIRE(a.size() > 20);
  for (std::size_t k = 0; k < a.size(); ++k) {
    INFO("generation " << k);
    REQUIRE(a[k].population.size() == b[k].population.size());
    CHECK(a[k].evaluations == b[k].evaluations);
    for (std::size_t i = 0; i < a[k].population.size(); ++i) {
      CHECK(a[k].population[i].x == b[k].population[i].x);
      CHECK(same(a[k].population[i].score, b[k].population[i].score));
    }
  }
  long skipped = 0, scored = 0;
  REQUIRE(lazy.scores.size() == full.scores.size());
  for (const auto& [x, s] : lazy.scores) {
    const auto it = full.scores.find(x);
    REQUIRE(it != full.scores.end());
    const opt::Score& f = it->second;
    if (!std::isinf(s.value)) {
      ++scored;
      CHECK(same(s, f));
      continue;
    }
    ++skipped;
    CHECK_FALSE(s.feasible);
    CHECK_FALSE(f.feasible);
    CHECK(s.violation == f.violation);
    CHECK(s.detail == f.detail);
    for (const double o : s.objectives) CHECK(std::isinf(o));
  }
  // Both kinds occur, or the comparison proves nothing.
  CHECK(skipped > 100);
  CHECK(scored > 100);
}
