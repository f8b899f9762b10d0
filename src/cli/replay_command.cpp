// mtcs replay: re-evaluates the populations a mold run stored, writes each replayed generation's
// feasible non-dominated front as CSV, JSON and a PNG plot (an animation-ready series with the
// same axes throughout), and the final front's layouts (YAML, bores CSV and STL); with --verify
// it fails unless every re-evaluated objective equals the stored one bit for bit.

#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>
#include <filesystem>
#include <sstream>
#include <memory>

#include "log.h"
#include "mtcs/cli/commands.h"
#include "mtcs/io/input_error.h"
#include "mtcs/store/run_store.h"
#include "mtcs/report/python_plot.h"
#include "mtcs/run/replay.h"
#include "mtcs/run/run_record.h"
#include "mtcs/run/session.h"

namespace mtcs::cli {
namespace {

namespace fs = std::filesystem;

struct ReplayOptions {
  std::string dir, mold;
  run::ReplayChoice choice;
  bool verify = false;
  bool plots = true;
};

int run_replay(const ReplayOptions& o) {
  const std::string db_path = (fs::path(o.dir) / "run.sqlite").string();
  if (!fs::exists(db_path)) throw io::InputError(db_path, 0, 0, "", "no stored run here");
  const store::RunStore db = store::RunStore::open(db_path);
  const auto meta = db.meta();
  if (!meta.count("mold")) throw io::InputError(db_path, 0, 0, "", "a test-problem run: nothing to replay against a mold");
  std::string mold_note;
  const run::Session session(run::stored_mold_spec(meta, o.mold, &mold_note), meta.at("config"), db_path + ":config");
  if (!mold_note.empty()) spdlog::warn(mold_note);

  std::ostringstream plot_log;
  bool plotted = false;
  const run::ReplayResult r = run::write_replay(session, db, o.dir, o.choice, [&](const fs::path& folder) {
    if (o.plots) plotted = report::render_plot("plot_fronts.py", {(folder / "frames.json").string()}, plot_log) &&
                           report::render_plot("plot_anytime.py", {(folder / "anytime.csv").string()}, plot_log);
  });
  const fs::path& out = r.folder;
  spdlog::info("re-evaluated {} individuals: {} objective mismatch(es); {} generation(s) replayed, fronts in {}/{}",
               r.checked, r.mismatches, r.generations, out.string(),
               o.choice.all || o.choice.every || o.choice.generation ? "" : " (a sample: --every N or --all for more)");
  if (!o.plots)
    spdlog::info("no front plots (--no-plots); render them with: {}",
                 report::plot_command("plot_fronts.py", {(out / "frames.json").string()}));
  else if (plotted)
    spdlog::info("front plots: {0}/front_*.png (an animation: ffmpeg -framerate 10 -pattern_type glob -i '{0}/front_*.png' "
                 "front.mp4)",
                 out.string());
  else
    spdlog::info(plot_log.str().substr(0, plot_log.str().empty() ? 0 : plot_log.str().size() - 1));
  return o.verify && r.mismatches > 0 ? 1 : 0;
}

}  // namespace

Command add_replay_command(CLI::App& app) {
  auto o = std::make_shared<ReplayOptions>();
  CLI::App* sub = app.add_subcommand(
      "replay",
      "Re-evaluate the populations of a stored mold run; for a sample of generations (--every,\n"
      "--all) write the feasible non-dominated front (DIR/replay/front_G.csv and .json), its plot (front_000G.png, numbered by\n"
      "generation, the same axes in every plot: an animation; when /usr/bin/python3 has matplotlib)\n"
      "and the last front's layouts (front_G_rankR.layout.yaml, .bores.csv, .bores.stl: every bore\n"
      "a closed cylinder mesh); anytime.csv and anytime.png: best feasible objective and front hypervolume\n"
      "against evaluations and wall time over every stored generation.\n"
      "DIR/replay is replaced whole at the end (never half-written).\n"
      "--verify: exit 1 unless every re-evaluated objective equals the stored one bit for bit.\n"
      "Example: mtcs replay runs/demo-plate --verify");
  sub->add_option("dir", o->dir, "run folder (with run.sqlite)")->required();
  sub->add_option("--generation", o->choice.generation, "only this stored generation");
  sub->add_option("--every", o->choice.every, "files for every N-th stored generation and the last (default: about " +
                                                  std::to_string(run::kReplaySample) + " evenly spaced)")
      ->check(CLI::Range(1, 1000000000));
  sub->add_flag("--all", o->choice.all, "files for every stored generation");
  sub->add_option("--mold", o->mold,
                  "the run's mold at a new place (default: the spec text stored in the run, or for a mold with\n"
                  "mesh files the stored path); a mold that differs from the run's is named with what changed");
  add_log_flags(sub);
  sub->add_flag("--verify", o->verify, "fail unless every stored generation re-evaluates to its objectives exactly");
  sub->add_flag("!--no-plots", o->plots, "no PNGs (about 0.1 s per generation); frames.json is still written");
  return {sub, [o] { return run_replay(*o); }};
}

}  // namespace mtcs::cli
