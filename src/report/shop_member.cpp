#include "shop_member.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "mtcs/mold/decoder.h"
#include "mtcs/mold/layout_io.h"
#include "mtcs/run/shop_layout.h"

namespace mtcs::report {

ShopMember shop_member(const run::Session& session, const opt::Genotype& x) {
  ShopMember m;
  const run::MoldProblem& problem = session.problem();
  m.genome = run::shop_layout(problem, session.scene(), problem.genome(x));
  m.layout = mold::decode(session.scene(), m.genome);
  m.plan = run::shop_plan(m.layout);
  m.score = problem.evaluate(problem.encode(m.genome));  // optimize_run's re-scoring, step for step
  return m;
}

namespace {

nlohmann::json polished_summary(const std::filesystem::path& dir) {
  std::ifstream in(dir / "summary.json");
  const nlohmann::json summary = nlohmann::json::parse(in, nullptr, false);
  if (summary.is_discarded() || !summary.contains("polish") || !summary["polish"].is_object() ||
      !summary["polish"].value("improved", false) || !summary.contains("best_objective") ||
      !summary["best_objective"].is_number())
    return nullptr;
  return summary;
}

}  // namespace

bool was_polished(const std::string& run_dir) { return !polished_summary(run_dir).is_null(); }

std::optional<ShopMember> polished_best(const std::string& run_dir, const run::Session& session, std::string& note) {
  const std::filesystem::path dir(run_dir);
  const nlohmann::json summary = polished_summary(dir);
  if (summary.is_null()) return std::nullopt;
  const double written = summary["best_objective"].get<double>();
  const std::string layout_file = (dir / "best.layout.yaml").string();
  std::optional<ShopMember> best;
  try {
    const mold::Genome genome = mold::read_layout(layout_file, session.spec()).genome;
    best = shop_member(session, session.problem().encode(genome));
  } catch (const std::exception&) {
    best.reset();  // gone or unreadable: as edited
  }
  const auto add = [&](const std::string& s) { note += (note.empty() ? "" : "; ") + s; };
  if (best && std::abs(best->score.value - written) <= 1e-9 * std::max(1.0, std::abs(written))) {
    add("the best member is the polished best of best.layout.yaml (objective " + std::to_string(written) +
        "); the run store keeps it unpolished (" + std::to_string(summary["polish"].value("before", 0.0)) + ")");
    return best;
  }
  add(layout_file + " no longer holds the polished best the run wrote (objective " + std::to_string(written) +
      "): the best member is the stored best, unpolished, rounded for the shop");
  return std::nullopt;
}

}  // namespace mtcs::report
