// mtcs replay: re-evaluates the populations a mold run stored, writes each replayed generation's
// feasible non-dominated front as CSV and JSON, and the final front's layouts; with --verify it
// fails unless every re-evaluated objective equals the stored one bit for bit.

#include <CLI/CLI.hpp>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "mold_problem.h"
#include "mtcs/cli/commands.h"
#include "mtcs/io/atomic_file.h"
#include "mtcs/io/input_error.h"
#include "mtcs/mold/decoder.h"
#include "mtcs/mold/layout_io.h"
#include "mtcs/opt/sms_emoa.h"
#include "mtcs/store/run_store.h"
#include "run_config.h"

namespace mtcs::cli {
namespace {

namespace fs = std::filesystem;

struct Options {
  std::string dir;
  std::optional<int> generation;
  bool verify = false;
};

int run_replay(const Options& o) {
  const std::string db_path = (fs::path(o.dir) / "run.sqlite").string();
  if (!fs::exists(db_path)) throw io::InputError(db_path, 0, 0, "", "no stored run here");
  const store::RunStore db = store::RunStore::open(db_path);
  const auto meta = db.meta();
  if (!meta.count("mold")) throw io::InputError(db_path, 0, 0, "", "a test-problem run: nothing to replay against a mold");
  const mold::Scene scene(mold::load_mold_spec(meta.at("mold")));
  const eval::Pipeline pipeline(scene);
  const auto names = pipeline.objective_names();
  const RunConfig config = parse_run_config(meta.at("config"), db_path + ":config", names);
  const MoldProblem problem(pipeline, config.weights, config.mutation);

  std::vector<int> indices;
  for (const auto& s : db.summaries())
    if (!o.generation || s.index == *o.generation) indices.push_back(s.index);
  if (indices.empty()) throw io::InputError(db_path, 0, 0, "generation", "no such stored generation");
  const fs::path out = fs::path(o.dir) / "replay";
  fs::create_directories(out);
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
    if (index == indices.back()) {
      // The layouts of the last replayed front, for CAD and re-scoring.
      for (const auto& m : front) {
        const int r = m["rank"];
        const mold::Genome genome = problem.genome(g.population[std::size_t(r)].x);
        const std::string stem = "front_" + std::to_string(index) + "_rank" + std::to_string(r);
        mold::save_layout((out / (stem + ".layout.yaml")).string(), genome);
        mold::save_bores_csv((out / (stem + ".bores.csv")).string(), mold::decode(scene, genome));
      }
    }
  }
  std::cerr << "replayed " << indices.size() << " generation(s), " << checked << " individuals: " << mismatches
            << " objective mismatch(es); fronts in " << out.string() << "/\n";
  return o.verify && mismatches > 0 ? 1 : 0;
}

}  // namespace

Command add_replay_command(CLI::App& app) {
  auto o = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand(
      "replay",
      "Re-evaluate the populations of a stored mold run; write each generation's feasible\n"
      "non-dominated front (DIR/replay/front_G.csv and .json) and the last one's layouts.\n"
      "--verify: exit 1 unless every re-evaluated objective equals the stored one bit for bit.\n"
      "Example: mtcs replay runs/demo-plate --verify");
  sub->add_option("dir", o->dir, "run folder (with run.sqlite)")->required();
  sub->add_option("--generation", o->generation, "only this stored generation");
  sub->add_flag("--verify", o->verify, "fail unless the replay reproduces every objective exactly");
  return {sub, [o] { return run_replay(*o); }};
}

}  // namespace mtcs::cli
