// mtcs evaluate: score one layout against a mold: objectives, violated constraints with the
// elements involved and where, the stages that ran and their time.

#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>

#include "mtcs/cli/commands.h"
#include "mtcs/eval/evaluation_report.h"
#include "mtcs/eval/pipeline.h"
#include "mtcs/mold/decoder.h"
#include "mtcs/mold/layout_io.h"
#include "mtcs/run/session.h"

namespace mtcs::cli {

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
                "one JSON object on stdout: {feasible, objectives, scalarised, violation, violations[{kind, elements, "
                "distance, margin, where}], drillable[{bore, free, cell, map, free_cells, pivot, tool, draw}] (with "
                "drilling.access_map), stages[{name, seconds}], changes[{circuit, waypoint, what}] (what reading the layout "
                "changed: snaps within 0.01 mm, diagonal steps drilled as axis-parallel legs)}");
  return {sub, [opt] {
            mold::MoldSpec spec = mold::load_mold_spec(opt->mold);  // the layout checked before the model
            const mold::WrittenLayout w = mold::read_layout(opt->layout, spec);
            const run::Session session(std::move(spec), run::RunOverrides{});
            const eval::Evaluation e = session.pipeline().evaluate(w.genome, true);
            const mold::Layout layout = mold::decode(session.scene(), w.genome);
            if (opt->json) eval::write_evaluation_json(std::cout, e, session.pipeline(), session.spec(), layout, w.changes);
            else eval::write_evaluation_text(std::cout, e, session.pipeline(), session.spec(), layout, w.changes);
            return 0;
          }};
}

}  // namespace mtcs::cli
