// mtcs replay: re-evaluates the populations a mold run stored, writes each replayed generation's
// feasible non-dominated front as CSV, JSON and a PNG plot (an animation-ready series with the
// same axes throughout), and the final front's layouts (YAML, bores CSV and STL); with --verify
// it fails unless every re-evaluated objective equals the stored one bit for bit.

#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <memory>

#include "log.h"
#include "mtcs/cli/commands.h"
#include "mtcs/io/input_error.h"
#include "mtcs/store/run_store.h"
#include "python_plot.h"
#include "mtcs/run/replay.h"
#include "mtcs/run/run_record.h"
#include "mtcs/run/session.h"

namespace mtcs::cli {
namespace {

namespace fs = std::filesystem;

struct Options {
  std::string dir, mold;
  std::optional<int> generation;
  bool verify = false;
  bool plots = true;
};

int run_replay(const Options& o) {
  const std::string db_path = (fs::path(o.dir) / "run.sqlite").string();
  if (!fs::exists(db_path)) throw io::InputError(db_path, 0, 0, "", "no stored run here");
  const store::RunStore db = store::RunStore::open(db_path);
  const auto meta = db.meta();
  if (!meta.count("mold")) throw io::InputError(db_path, 0, 0, "", "a test-problem run: nothing to replay against a mold");
  std::string mold_note;
  const run::Session session(run::stored_mold_spec(meta, o.mold, &mold_note), meta.at("config"), db_path + ":config");
  if (!mold_note.empty()) spdlog::warn(mold_note);
  const fs::path out = fs::path(o.dir) / "replay";
  const run::Replay r = run::replay_fronts(db, session, o.generation, out.string());
  if (r.generations == 0) throw io::InputError(db_path, 0, 0, "generation", "no such stored generation");
  spdlog::info("replayed {} generation(s), {} individuals: {} objective mismatch(es); fronts in {}/", r.generations, r.checked,
               r.mismatches, out.string());
  std::ostringstream plot_log;
  if (!o.plots)
    spdlog::info("no front plots (--no-plots); render them with: {}",
                 plot_command("plot_fronts.py", {(out / "frames.json").string()}));
  else if (render_plot("plot_fronts.py", {(out / "frames.json").string()}, plot_log))
    spdlog::info("front plots: {0}/front_*.png (an animation: ffmpeg -framerate 10 -pattern_type glob -i '{0}/front_*.png' "
                 "front.mp4)",
                 out.string());
  else
    spdlog::info(plot_log.str().substr(0, plot_log.str().empty() ? 0 : plot_log.str().size() - 1));
  return o.verify && r.mismatches > 0 ? 1 : 0;
}

}  // namespace

Command add_replay_command(CLI::App& app) {
  auto o = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand(
      "replay",
      "Re-evaluate the populations of a stored mold run; write each generation's feasible\n"
      "non-dominated front (DIR/replay/front_G.csv and .json), its plot (front_000G.png, numbered by\n"
      "generation, the same axes in every plot: an animation; when /usr/bin/python3 has matplotlib)\n"
      "and the last front's layouts (front_G_rankR.layout.yaml, .bores.csv, .bores.stl: every bore\n"
      "a closed cylinder mesh).\n"
      "--verify: exit 1 unless every re-evaluated objective equals the stored one bit for bit.\n"
      "Example: mtcs replay runs/demo-plate --verify");
  sub->add_option("dir", o->dir, "run folder (with run.sqlite)")->required();
  sub->add_option("--generation", o->generation, "only this stored generation");
  sub->add_option("--mold", o->mold,
                  "the run's mold at a new place (default: the spec text stored in the run, or for a mold with\n"
                  "mesh files the stored path); a mold that differs from the run's is named with what changed");
  add_log_flags(sub);
  sub->add_flag("--verify", o->verify, "fail unless the replay reproduces every objective exactly");
  sub->add_flag("!--no-plots", o->plots, "no PNGs (about 0.1 s per generation); frames.json is still written");
  return {sub, [o] { return run_replay(*o); }};
}

}  // namespace mtcs::cli
