// The ES and SMS-EMOA score an offspring without its objectives when the mold problem sees it is
// infeasible and every parent feasible (constrained domination: such a child is never kept). The
// run must be the run that scores every child: the same generations bit for bit, each skipped
// child infeasible with the violations a full evaluation gives it, every other child's objectives
// equal. The same for a multi-fidelity ES, whose screen skips them too.

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
  opt::Score screen(const opt::Genotype& g) const override { return kept(g, inner_.screen(g), true); }
  opt::Score screen_unless_behind(const opt::Genotype& g, const opt::Score& bar) const override {
    return lazy_ ? kept(g, inner_.screen_unless_behind(g, bar), true) : screen(g);
  }

  std::map<opt::Genotype, opt::Score> scores, screens;

 private:
  opt::Score kept(const opt::Genotype& g, opt::Score s, bool screen = false) const {
    const std::lock_guard<std::mutex> hold(lock_);
    (screen ? const_cast<Scored*>(this)->screens : const_cast<Scored*>(this)->scores)[g] = s;
    return s;
  }
  bool lazy_;
  mutable std::mutex lock_;
};

std::vector<opt::Generation> optimised(const std::string& algorithm, const opt::Problem& problem, long evaluations,
                                       std::size_t objectives, int survivors = 0) {
  std::vector<opt::Generation> seen;
  const auto keep = [&](const opt::Generation& g) { seen.push_back(g); };
  if (algorithm == "es") {
    opt::EsConfig c;
    c.seed = 3;
    c.evaluations = evaluations;
    c.survivors = survivors;
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

// Two runs, every child scored (a) and infeasible children skipped (b): the same generations,
// and each of b's scores the full one or an infeasible child's without objectives; at least
// so many of each kind, or the comparison proves nothing.
void check_same_run(const std::vector<opt::Generation>& a, const std::vector<opt::Generation>& b,
                    const std::map<opt::Genotype, opt::Score>& full, const std::map<opt::Genotype, opt::Score>& lazy,
                    long least_skipped, long least_scored) {
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
  REQUIRE(lazy.size() == full.size());
  for (const auto& [x, s] : lazy) {
    const auto it = full.find(x);
    REQUIRE(it != full.end());
    const opt::Score& f = it->second;
    if (!std::isinf(s.value)) {
      ++scored;
      CHECK(same(s, f));
      continue;
    }
    ++skipped;
    CHECK_FALSE(s.feasible);
    CHECK_FALSE(f.feasible);
    // Skipped, a layout lacks its eject verdict (it needs the solve; listed first): the rest as
    // the full evaluation has it.
    if (f.detail.rfind("eject ", 0) != 0) {
      CHECK(s.violation == f.violation);
      CHECK(s.detail == f.detail);
    } else {
      REQUIRE(f.detail.find("; ") != std::string::npos);
      CHECK(s.violation < f.violation);
      CHECK(s.detail == f.detail.substr(f.detail.find("; ") + 2));
    }
    for (const double o : s.objectives) CHECK(std::isinf(o));
  }
  CHECK(skipped >= least_skipped);
  CHECK(scored >= least_scored);
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

  check_same_run(a, b, full.scores, lazy.scores, 100, 100);
}

TEST_CASE("Multi-fidelity ES: infeasible children of feasible parents skip the screen's objectives too, the run unchanged",
          "[run][es][fidelity][skip]") {
  // A cheap screen (T2d, M = 2, one wall level, samples 22 mm apart), 10 of 40 re-scored.
  const std::string config =
      "fidelity: {screen: t2d, elements_per_bore: 2, wall_images: 1, sample_spacing: 22, survivors: 10}\n";
  const std::string mold = MTCS_SOURCE_DIR + "/molds/plate.yaml";
  const run::Session full_session(mold::load_mold_spec(mold), config, "test"),
      lazy_session(mold::load_mold_spec(mold), config, "test");
  REQUIRE(full_session.config().es.survivors == 10);
  const Scored full(full_session.problem(), false), lazy(lazy_session.problem(), true);
  const std::size_t m = full_session.spec().objectives.use.size();
  const auto a = optimised("es", full, 1500, m, 10), b = optimised("es", lazy, 1500, m, 10);
  check_same_run(a, b, full.screens, lazy.screens, 100, 100);
  check_same_run(a, b, full.scores, lazy.scores, 0, 100);
  // Only the survivors were scored by the spec's tier.
  CHECK(full.scores.size() < full.screens.size() / 3);
}
