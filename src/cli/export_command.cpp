// mtcs export: a layout's bores as STEP, VTP, OBJ or CSV, from a stored run's member or from a
// mold and a layout file (report::export_bores writes them); this file parses and prints.

#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>
#include <memory>

#include "log.h"
#include "mtcs/cli/commands.h"
#include "mtcs/report/layout_export.h"

namespace mtcs::cli {

Command add_export_command(CLI::App& app) {
  auto o = std::make_shared<report::ExportRequest>();
  CLI::App* sub = app.add_subcommand(
      "export",
      "A layout's bores for CAD and viewers, as the shop drills them (bores.csv's hole ends): step\n"
      "(AP214, one named solid per bore; needs the optional OpenCASCADE component), vtp (ParaView:\n"
      "closed tubes with circuit, bore and diameter per cell), obj (one object per bore) or csv (the\n"
      "bores table). The layout is a stored run's member (RUN_DIR [--generation G] [--member K]:\n"
      "default the last generation's best) or a layout file (MOLD.yaml --layout L.yaml).\n"
      "Example: mtcs export runs/demo-plate --format step --out bores.step");
  sub->add_option("source", o->source, "run folder (with run.sqlite), or a mold spec with --layout")->required();
  sub->add_option("--layout", o->layout_file, "layout (YAML) of the mold given as source");
  sub->add_option("--generation", o->generation, "stored generation (default: the last)");
  sub->add_option("--member", o->member, "its member by rank (default: the best, as best.layout.yaml; SMS-EMOA's need not be rank 0)");
  sub->add_option("--format", o->format, "step, vtp, obj or csv")->check(CLI::IsMember({"step", "vtp", "obj", "csv"}));
  sub->add_option("--out", o->out,
                  "the file (default: RUN_DIR/exports/generation_G_member_K.FORMAT, or beside the layout\n"
                  "file: L.FORMAT)");
  add_log_flags(sub);
  return {sub, [o] {
            const report::Exported e = report::export_bores(*o);
            if (!e.note.empty()) spdlog::warn(e.note);
            spdlog::info("export: {} bores to {}", e.bores, e.path);
            return 0;
          }};
}

}  // namespace mtcs::cli
