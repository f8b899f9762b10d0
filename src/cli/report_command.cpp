// mtcs report: the HTML page of a stored run (report::run_report builds it); this file parses
// and prints.

#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>
#include <filesystem>
#include <memory>

#include "log.h"
#include "mtcs/cli/commands.h"
#include "mtcs/io/atomic_file.h"
#include "mtcs/report/run_report.h"

namespace mtcs::cli {

Command add_report_command(CLI::App& app) {
  struct Options {
    std::string dir, out;
    report::ReportOptions report;
  };
  auto o = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand(
      "report",
      "Write one self-contained HTML page of a stored mold run (opens from disk, no network): a 3-D\n"
      "view of a layout in its block (part, keep-outs, bores by circuit with inlets and outlets,\n"
      "violated clearances between their closest points, the cavity temperature; layers, section\n"
      "plane), the Pareto front of a generation (click a point to load its layout) and the run's\n"
      "convergence (best/median value, feasible share, hypervolume).\n"
      "Example: mtcs report runs/demo-plate --out runs/demo-plate/report.html");
  sub->add_option("dir", o->dir, "run folder (with run.sqlite)")->required();
  sub->add_option("--out", o->out, "the page (default: DIR/report.html)");
  sub->add_option("--generation", o->report.generation, "the stored generation whose layouts are shown (default: the last)");
  sub->add_option("--member", o->report.member, "its layout shown first, by rank (default: the best, as best.layout.yaml; SMS-EMOA's need not be rank 0)");
  sub->add_option("--mold", o->report.mold, "the run's mold at a new place (as for replay)");
  sub->add_flag("!--no-temperature", o->report.temperature, "no cavity temperature (skips one thermal solve)");
  add_log_flags(sub);
  return {sub, [o] {
            const report::RunReport r = report::run_report(o->dir, o->report);
            if (!r.note.empty()) spdlog::warn(r.note);
            const std::string out = o->out.empty() ? (std::filesystem::path(o->dir) / "report.html").string() : o->out;
            io::AtomicFile file(out);
            file.stream() << r.html;
            file.commit();
            spdlog::info("report: {} ({:.2f} MB): generation {}, {} layouts ({} point{} on the front), member {} shown ({} bores){}, "
                         "{} generations charted",
                         out, double(r.html.size()) / 1e6, r.generation, r.members, r.front, r.front == 1 ? "" : "s", r.member, r.bores,
                         r.temperature ? " with its cavity temperature" : "", r.generations);
            return 0;
          }};
}

}  // namespace mtcs::cli
