#include "mtcs/run/optimize_run.h"

#include <spdlog/spdlog.h>

#include <filesystem>
#include <map>

#include "mtcs/io/input_error.h"
#include "mtcs/mold/decoder.h"
#include "mtcs/run/polish.h"
#include "mtcs/run/progress_line.h"
#include "mtcs/run/run_outputs.h"
#include "mtcs/run/run_record.h"
#include "mtcs/run/session.h"
#include "mtcs/run/shop_layout.h"
#include "mtcs/run/stored_run.h"
#include "mtcs/store/run_store.h"

namespace mtcs::run {

namespace fs = std::filesystem;

OptimizeResult optimize_mold(const OptimizeRequest& r, const ProgressFactory& make_progress,
                             const std::function<bool()>& stop) {
  const bool resuming = !r.resume.empty();
  const std::string out_dir = resuming ? r.resume : r.out;
  const std::string db_path = (fs::path(out_dir) / "run.sqlite").string();
  std::optional<store::RunStore> db;
  std::string mold_path = r.mold, config_text;
  int polish_budget = r.polish;
  if (resuming) {
    if (!fs::exists(db_path)) throw io::InputError(db_path, 0, 0, "", "no run to resume here");
    db = store::RunStore::resume(db_path);
    const auto meta = db->meta();
    for (const char* key : {"mold", "mold_hash", "config"})
      if (!meta.count(key)) throw io::InputError(db_path, 0, 0, key, "missing from the store: not a mold run to resume");
    mold_path = meta.at("mold");
    config_text = meta.at("config");
    // The run's polish budget is part of the run: a resume polishes as the run would have.
    if (meta.count("polish") && r.polish == 0) {
      try {
        polish_budget = std::stoi(meta.at("polish"));
      } catch (const std::exception&) {
        throw io::InputError(db_path, 0, 0, "polish", "not a whole number in the store's meta: " + meta.at("polish"));
      }
    }
    if (content_hash(read_file_text(mold_path)) != meta.at("mold_hash"))
      throw io::InputError(mold_path, 0, 0, "", "the mold spec changed since the run started; start a new run");
  }
  // A resumed run keeps its stored config; a new one resolves RUN.yaml and the command line.
  const Session session = resuming ? Session(mold::load_mold_spec(mold_path), config_text, db_path + ":config")
                                   : Session(mold::load_mold_spec(mold_path), r.overrides);
  const mold::Scene& scene = session.scene();
  const std::vector<std::string>& names = session.objective_names();
  const RunConfig& config = session.config();
  if (!resuming) {
    if (r.prepare_out) r.prepare_out(out_dir);
    if (store::RunStore::in_use(db_path))
      throw io::InputError(db_path, 0, 0, "", "the run here is in use: another process writes it; choose --out");
    if (fs::exists(db_path))
      throw io::InputError(db_path, 0, 0, "", "a run exists here: resume it with --resume " + out_dir + " or choose --out");
    auto meta = mold_run_meta(mold_path, session);
    if (r.polish > 0) meta["polish"] = std::to_string(r.polish);
    db = store::RunStore::create(db_path, meta);
  }

  const MoldProblem& problem = session.problem();
  const MoldOptimizer optimizer(problem, scene, config);
  spdlog::debug("mold {}: {} surface samples; run config:\n{}", mold_path, session.pipeline().surface_samples(),
                config.to_yaml(names));
  if (optimizer.pareto()) spdlog::info(hypervolume_basis(optimizer, names));
  const StoredRun stored = run_stored(optimizer, problem, *db, make_progress(optimizer, config.log_every), stop);
  const opt::Generation& last = stored.last;

  // The best layout, for CAD and for re-scoring with mtcs evaluate; optionally polished.
  const opt::Individual& first = last.population.front();
  RunOutcome outcome{last, first.score, problem.genome(first.x), stored.seconds, mold_path, std::nullopt, first.score.value};
  outcome.interrupted = stored.interrupted;
  if (polish_budget > 0 && !stored.interrupted) {
    outcome.polished = polish(problem, scene, outcome.genome, polish_budget);
    if (outcome.polished->improved) outcome.genome = outcome.polished->genome, outcome.best = outcome.polished->score;
    spdlog::info("polish (COBYLA, {} evaluations): objective {:.6g}{}", outcome.polished->evaluations, outcome.best.value,
                 outcome.polished->improved ? "" : " (no improvement)");
  }
  // What is written is rounded to the tolerance and tidied, and scored as written.
  outcome.genome = shop_layout(scene, outcome.genome);
  outcome.best = problem.evaluate(problem.encode(outcome.genome));
  const mold::Layout layout = write_run_outputs(out_dir, scene, optimizer, names, config.es.seed, outcome);
  spdlog::info("{} best layout: {} bores in {} circuits, objective {:.6g}, {} evaluations in {:.6g} s",
               outcome.best.feasible ? "feasible" : "INFEASIBLE", layout.bores.size(), outcome.genome.circuits.size(),
               outcome.best.value, last.evaluations, stored.seconds);
  spdlog::info("results in {}/: best.layout.yaml (mtcs evaluate {} --layout {}/best.layout.yaml), bores.csv, holes.csv, "
               "bores.stl, summary.json, run.sqlite",
               out_dir, mold_path, out_dir);
  for (const std::string& w : front_warnings(optimizer, last)) spdlog::warn(w);
  return {out_dir, mold_path, stored.interrupted, last.index, last.evaluations, optimizer.budget()};
}

}  // namespace mtcs::run
