// mtcs replay: re-evaluates the populations a mold run stored, writes each replayed generation's
// feasible non-dominated front as CSV, JSON and a PNG plot (an animation-ready series with the
// same axes throughout), and the final front's layouts (YAML, bores CSV and STL); with --verify
// it fails unless every re-evaluated objective equals the stored one bit for bit.

#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>
#include <filesystem>
#include <iostream>
#include <limits>
#include <sstream>
#include <memory>
#include <nlohmann/json.hpp>

#include "log.h"
#include "mtcs/cli/commands.h"
#include "mtcs/io/atomic_file.h"
#include "mtcs/io/input_error.h"
#include "mtcs/mold/decoder.h"
#include "mtcs/mold/layout_io.h"
#include "mtcs/opt/sms_emoa.h"
#include "mtcs/store/run_store.h"
#include "python_plot.h"
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

// Per objective, [lowest, highest] over the feasible fronts of every stored generation: the
// axes of every plot, so that an animation of them holds still.
nlohmann::ordered_json front_limits(const store::RunStore& db, std::size_t objectives) {
  std::vector<std::pair<double, double>> limits(objectives, {std::numeric_limits<double>::infinity(),
                                                             -std::numeric_limits<double>::infinity()});
  for (const auto& s : db.summaries())
    for (const auto& p : opt::SmsEmoa::front(*db.generation(s.index)))
      for (std::size_t k = 0; k < objectives && k < p.size(); ++k)
        limits[k] = {std::min(limits[k].first, p[k]), std::max(limits[k].second, p[k])};
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const auto& [lo, hi] : limits) out.push_back(lo <= hi ? nlohmann::ordered_json{lo, hi} : nlohmann::ordered_json{0, 1});
  return out;
}

int run_replay(const Options& o) {
  const std::string db_path = (fs::path(o.dir) / "run.sqlite").string();
  if (!fs::exists(db_path)) throw io::InputError(db_path, 0, 0, "", "no stored run here");
  const store::RunStore db = store::RunStore::open(db_path);
  const auto meta = db.meta();
  if (!meta.count("mold")) throw io::InputError(db_path, 0, 0, "", "a test-problem run: nothing to replay against a mold");
  std::string mold_note;
  const run::Session session(run::stored_mold_spec(meta, o.mold, &mold_note), meta.at("config"), db_path + ":config");
  if (!mold_note.empty()) spdlog::warn(mold_note);
  const mold::Scene& scene = session.scene();
  const std::vector<std::string>& names = session.objective_names();
  const run::MoldProblem& problem = session.problem();

  std::vector<int> indices;
  const auto summaries = db.summaries();
  for (const auto& s : summaries)
    if (!o.generation || s.index == *o.generation) indices.push_back(s.index);
  if (indices.empty()) throw io::InputError(db_path, 0, 0, "generation", "no such stored generation");
  const fs::path out = fs::path(o.dir) / "replay";
  fs::create_directories(out);
  // The plots: one PNG per replayed generation, numbered by generation with the width of the
  // run's largest index (so that they sort), and axes that fit every stored front.
  const std::size_t width = std::max<std::size_t>(4, std::to_string(summaries.back().index).size());
  nlohmann::ordered_json frames{{"objectives", names}, {"limits", front_limits(db, names.size())},
                                {"frames", nlohmann::ordered_json::array()}};
  long checked = 0, mismatches = 0;
  for (const int index : indices) {
    const opt::Generation g = *db.generation(index);
    nlohmann::ordered_json front = nlohmann::ordered_json::array();
    io::AtomicFile csv((out / ("front_" + std::to_string(index) + ".csv")).string());
    csv.stream() << "rank";
    for (const auto& n : names) csv.stream() << ',' << n;
    csv.stream() << '\n';
    const auto points = opt::SmsEmoa::front(g);
    for (std::size_t r = 0; r < g.population.size(); ++r) {
      const auto& ind = g.population[r];
      const opt::Score again = problem.evaluate(ind.x);
      ++checked;
      if (again.objectives != ind.score.objectives || again.violation != ind.score.violation) ++mismatches;
      if (!ind.score.feasible ||
          std::find(points.begin(), points.end(), ind.score.objectives) == points.end())
        continue;
      csv.stream() << r;
      nlohmann::ordered_json member{{"rank", r}};
      for (std::size_t k = 0; k < names.size(); ++k) {
        csv.stream() << ',' << ind.score.objectives[k];
        member["objectives"][names[k]] = ind.score.objectives[k];
      }
      csv.stream() << '\n';
      front.push_back(member);
    }
    csv.commit();
    io::AtomicFile json((out / ("front_" + std::to_string(index) + ".json")).string());
    json.stream() << nlohmann::ordered_json{{"generation", index}, {"evaluations", g.evaluations}, {"front", front}}.dump(2)
                  << '\n';
    json.commit();
    std::string number = std::to_string(index);
    number.insert(0, width - std::min(width, number.size()), '0');
    frames["frames"].push_back({{"generation", index},
                                {"evaluations", g.evaluations},
                                {"front", "front_" + std::to_string(index) + ".json"},
                                {"png", "front_" + number + ".png"}});
    if (index == indices.back()) {
      // The layouts of the last replayed front, for CAD and re-scoring: one STL per member.
      for (const auto& m : front) {
        const int r = m["rank"];
        const mold::Genome genome = problem.genome(g.population[std::size_t(r)].x);
        const mold::Layout layout = mold::decode(scene, genome);
        const std::string stem = "front_" + std::to_string(index) + "_rank" + std::to_string(r);
        mold::save_layout((out / (stem + ".layout.yaml")).string(), genome);
        mold::save_bores_csv((out / (stem + ".bores.csv")).string(), layout);
        mold::save_bores_stl((out / (stem + ".bores.stl")).string(), layout);
      }
    }
  }
  io::AtomicFile frames_file((out / "frames.json").string());
  frames_file.stream() << frames.dump(1) << '\n';
  frames_file.commit();
  spdlog::info("replayed {} generation(s), {} individuals: {} objective mismatch(es); fronts in {}/", indices.size(), checked,
               mismatches, out.string());
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
  return o.verify && mismatches > 0 ? 1 : 0;
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
