// mtcs export: a layout's bores as VTP, OBJ or CSV, from a stored run's member or from a mold and
// a layout file (report::export_layout writes them); this file parses and prints.

#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>
#include <filesystem>
#include <memory>

#include "log.h"
#include "mtcs/cli/commands.h"
#include "mtcs/mold/decoder.h"
#include "mtcs/mold/layout_io.h"
#include "mtcs/report/layout_export.h"

namespace mtcs::cli {

Command add_export_command(CLI::App& app) {
  struct Options {
    std::string source, layout, format = "vtp", out;
    std::optional<int> generation, member;
  };
  auto o = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand(
      "export",
      "A layout's bores for CAD and viewers: vtp (ParaView: closed tubes with circuit, bore and\n"
      "diameter per cell), obj (one object per bore) or csv (the bores table). The layout is a\n"
      "stored run's member (RUN_DIR [--generation G] [--member K]: default the last generation's\n"
      "best) or a layout file (MOLD.yaml --layout L.yaml). STEP is not built yet.\n"
      "Example: mtcs export runs/demo-plate --format obj --out bores.obj");
  sub->add_option("source", o->source, "run folder (with run.sqlite), or a mold spec with --layout")->required();
  sub->add_option("--layout", o->layout, "layout (YAML) of the mold given as source");
  sub->add_option("--generation", o->generation, "stored generation (default: the last)");
  sub->add_option("--member", o->member, "its member by rank (default: 0, the best)");
  sub->add_option("--format", o->format, "vtp, obj or csv")->check(CLI::IsMember({"vtp", "obj", "csv", "step"}));
  sub->add_option("--out", o->out, "the file (default: SOURCE's folder/bores.FORMAT)");
  add_log_flags(sub);
  return {sub, [o] {
            if (o->format == "step") {
              std::cerr << "mtcs export: --format step: not built (STEP needs OpenCASCADE; use vtp, obj or csv)\n";
              return 2;
            }
            std::unique_ptr<run::Session> session;
            mold::Layout layout;
            if (!o->layout.empty()) {
              session = std::make_unique<run::Session>(o->source);
              layout = mold::decode(session->scene(), session->read_layout(o->layout));
            } else {
              report::StoredLayout s = report::stored_layout(o->source, o->generation, o->member);
              if (!s.note.empty()) spdlog::warn(s.note);
              layout = std::move(s.layout);
            }
            const std::filesystem::path folder = o->layout.empty() ? std::filesystem::path(o->source) : std::filesystem::path(o->source).parent_path();
            const std::string out = o->out.empty() ? (folder / ("bores." + o->format)).string() : o->out;
            report::export_layout(out, layout, *report::export_format(o->format));
            spdlog::info("export: {} bores to {}", layout.bores.size(), out);
            return 0;
          }};
}

}  // namespace mtcs::cli
