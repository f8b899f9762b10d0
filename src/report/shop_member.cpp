#include "shop_member.h"

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "mtcs/mold/decoder.h"
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

std::string polish_note(const std::string& run_dir) {
  std::ifstream in(std::filesystem::path(run_dir) / "summary.json");
  const nlohmann::json summary = nlohmann::json::parse(in, nullptr, false);
  if (summary.is_discarded() || !summary.contains("polish") || !summary["polish"].value("improved", false)) return "";
  const std::string mold =
      summary.contains("mold") && summary["mold"].is_string() ? summary["mold"].get<std::string>() : "MOLD.yaml";
  return "best.layout.yaml and bores.csv hold the best after a polish (objective " +
         std::to_string(summary["polish"].value("after", 0.0)) +
         ") that the run store does not keep; this is the last generation's best as stored, rounded for the shop "
         "(the polished one: mtcs export " + mold + " --layout " + (std::filesystem::path(run_dir) / "best.layout.yaml").string() +
         ")";
}

}  // namespace mtcs::report
