// mtcs evaluate: score one layout against a mold: objectives, violated constraints with the
// elements involved and where, the stages that ran and their time.

#include <CLI/CLI.hpp>
#include <iomanip>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>

#include "mtcs/cli/commands.h"
#include "mtcs/eval/pipeline.h"
#include "mtcs/mold/decoder.h"
#include "mtcs/mold/layout_io.h"
#include "mtcs/run/session.h"

namespace mtcs::cli {

namespace {

nlohmann::ordered_json to_json(const eval::Evaluation& e, const eval::Pipeline& pipeline) {
  nlohmann::ordered_json j;
  j["feasible"] = e.feasible();
  j["objectives"] = nlohmann::ordered_json::object();
  const auto names = pipeline.objective_names();
  for (std::size_t k = 0; k < names.size(); ++k) j["objectives"][names[k]] = e.objectives[k];
  j["violation"] = e.violation;
  j["violations"] = nlohmann::ordered_json::array();
  for (const auto& v : e.violations) {
    j["violations"].push_back({{"kind", eval::to_string(v.kind)},
                               {"elements", v.elements},
                               {"distance", v.distance},
                               {"margin", v.margin},
                               {"where", {v.where.x(), v.where.y(), v.where.z()}}});
  }
  j["stages"] = nlohmann::ordered_json::array();
  for (const auto& s : e.stages) j["stages"].push_back({{"name", s.name}, {"seconds", s.seconds}});
  return j;
}

// What a violation found against what its rule needs, with units: clearances and port offsets
// in mm, the depth limit as a depth/diameter ratio, the entry angle in degrees.
std::string found_and_needed(const eval::Violation& v) {
  std::ostringstream s;
  s << std::setprecision(10);
  using K = eval::ViolationKind;
  switch (v.kind) {
    case K::DepthRatio: s << "depth/diameter " << v.distance << ", at most " << v.margin; break;
    case K::EntryAngle: s << "entry angle " << v.distance << " deg, at most " << v.margin << " deg"; break;
    case K::EntryFace: s << "drilled from a face that is not allowed"; break;
    case K::InletFace:
    case K::OutletFace: s << v.distance << " mm from the nearest allowed face"; break;
    case K::BoreBore:
    case K::BoreKeepout:
    case K::BoreCavity:
    case K::BoreSurface: s << "found " << v.distance << " mm, needs " << v.margin << " mm"; break;
  }
  return s.str();
}

void print_text(const eval::Evaluation& e, const eval::Pipeline& pipeline, const mold::Layout& layout) {
  double dead = 0;
  for (const auto& b : layout.bores) dead += b.dead_end;
  std::cout << "bores " << layout.bores.size() << ", plugs " << layout.plugs << " (dead ends " << dead
            << " mm), designed junctions " << layout.junctions.size() << ", surface samples "
            << pipeline.surface_samples() << "\n\nobjectives\n";
  const auto names = pipeline.objective_names();
  for (std::size_t k = 0; k < names.size(); ++k)
    std::cout << "  " << std::left << std::setw(16) << names[k] << std::setprecision(10) << e.objectives[k] << "\n";
  std::cout << "\n" << (e.feasible() ? "feasible" : "infeasible") << ": " << e.violations.size()
            << " violated constraint(s), total violation " << e.violation << "\n";
  for (const auto& v : e.violations) {
    std::cout << "  " << std::setw(14) << eval::to_string(v.kind) << " ";
    for (const auto& el : v.elements) std::cout << el << " ";
    std::cout << found_and_needed(v) << " at (" << v.where.x() << ", " << v.where.y() << ", " << v.where.z() << ") mm\n";
  }
  std::cout << "\nstages (microseconds)\n";
  for (const auto& s : e.stages) std::cout << "  " << std::setw(24) << s.name << s.seconds * 1e6 << "\n";
}

}  // namespace

Command add_evaluate_command(CLI::App& app) {
  struct Options {
    std::string mold, layout;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand(
      "evaluate",
      "Score a layout against a mold: objectives, every violated constraint with the elements\n"
      "involved, the distance found and where, and the time of each stage that ran.\n"
      "Example: mtcs evaluate molds/plate.yaml --layout molds/plate.layout.yaml --json");
  sub->add_option("mold", opt->mold, "mold spec (YAML, see docs/mold-spec.md)")->required();
  sub->add_option("--layout", opt->layout, "layout (YAML: circuits of waypoints)")->required();
  sub->add_flag("--json", opt->json,
                "one JSON object on stdout: {feasible, objectives, violation, violations[{kind, elements, "
                "distance, margin, where}], stages[{name, seconds}]}");
  return {sub, [opt] {
            const run::Session session(opt->mold);
            const mold::Genome genome = mold::load_layout(opt->layout, session.spec());
            const eval::Evaluation e = session.pipeline().evaluate(genome, true);
            if (opt->json) std::cout << to_json(e, session.pipeline()).dump(2) << "\n";
            else print_text(e, session.pipeline(), mold::decode(session.scene(), genome));
            return 0;
          }};
}

}  // namespace mtcs::cli
