#include "mtcs/run/optimize_run.h"

#include <spdlog/spdlog.h>

#include <filesystem>
#include <map>

#include "mtcs/eval/evaluation_report.h"
#include "mtcs/io/input_error.h"
#include "mtcs/mold/decoder.h"
#include "mtcs/mold/layout_io.h"
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

namespace {

constexpr std::size_t kViolationsShown = 8;  // on the screen after a run; summary.json lists all

// The process's island transport: MPI when mpirun started it, threads for --islands P, none for
// one population.
std::unique_ptr<IslandTransport> transport_for(const OptimizeRequest& r) {
  const int ranks = mpi_launch_size();
  if (ranks == 0) return r.islands.islands > 0 || !r.resume.empty() ? thread_transport() : nullptr;
  if (r.resume.empty() && r.islands.islands != ranks)
    throw io::InputError("", 0, 0, "--islands",
                         "started by mpirun with " + std::to_string(ranks) + " ranks: give --islands " + std::to_string(ranks));
  auto mpi = mpi_transport();
  if (!mpi) throw io::InputError("", 0, 0, "--islands", "started by mpirun, but this mtcs was built without MPI");
  return mpi;
}

// A run's folder stands for the layout it wrote.
std::string start_layout_path(const std::string& given) {
  return fs::is_directory(given) ? (fs::path(given) / "best.layout.yaml").string() : given;
}

// No run and no writer in the output folder yet. Checked before the thermal model is built
// (seconds on a part) and again before the store is made.
void check_out_free(const std::string& db_path, const std::string& out_dir) {
  if (store::RunStore::in_use(db_path))
    throw io::InputError(db_path, 0, 0, "", "the run here is in use: another process writes it; choose --out");
  if (fs::exists(db_path))
    throw io::InputError(db_path, 0, 0, "", "a run exists here: resume it with --resume " + out_dir + " or choose --out");
}

// The --start layouts as genotypes, each read as `mtcs evaluate --layout` reads it and scored
// once, so that the user can compare the run's best with it.
std::vector<opt::Genotype> start_genotypes(const std::vector<std::string>& paths, const Session& session) {
  const int mu = session.config().es.mu;
  if (int(paths.size()) > mu)
    throw io::InputError("", 0, 0, "--start", std::to_string(paths.size()) + " layouts, more than the population (mu " +
                                                  std::to_string(mu) + ")");
  const mold::CircuitLimits& lim = session.spec().circuits;
  std::vector<opt::Genotype> start;
  for (const std::string& given : paths) {
    const std::string path = start_layout_path(given);
    const mold::Genome genome = session.read_layout(path);
    start.push_back(session.problem().encode(genome));
    const opt::Score s = session.problem().evaluate(start.back());
    if (s.feasible)
      spdlog::info("start layout {}: objective {:.6g}", path, s.value);
    else
      spdlog::warn("start layout {} is INFEASIBLE ({}): the search keeps it only while nothing feasible beats it", path,
                   s.detail);
    // Kept as it is; its children's circuit moves head for the spec's range (of drilled circuits:
    // baffles and bubblers count against drilling.baffles.max).
    if (const int k = int(genome.circuits.size()) - count_blind(genome); k < lim.min || k > lim.max)
      spdlog::warn("start layout {} has {} drilled circuit{}; the search makes {}-{} (circuits.min, circuits.max): its "
                   "children add or remove circuits toward that",
                   path, k, k == 1 ? "" : "s", lim.min, lim.max);
  }
  return start;
}

}  // namespace

OptimizeResult optimize_mold(const OptimizeRequest& r, const ProgressFactory& make_progress,
                             const std::function<bool()>& stop) {
  std::unique_ptr<IslandTransport> transport = transport_for(r);
  const bool writer = !transport || transport->writer();
  const bool resuming = !r.resume.empty();
  const std::string out_dir = resuming ? r.resume : r.out;
  const std::string db_path = (fs::path(out_dir) / "run.sqlite").string();
  std::optional<store::RunStore> db;
  std::unique_ptr<const Session> made;
  IslandSettings islands = r.islands;
  std::string mold_path = r.mold;
  int polish_budget = r.polish;
  std::vector<opt::Genotype> start;
  // Opens or makes the store (the writer) and the session; under MPI every rank learns whether
  // all could, so that none waits for a failed one.
  auto set_up = [&] {
    std::string config_text;
    if (resuming) {
      if (!fs::exists(db_path)) throw io::InputError(db_path, 0, 0, "", "no run to resume here");
      if (writer) db = store::RunStore::resume(db_path);
      const auto meta = writer ? db->meta() : store::RunStore::open(db_path).meta();
      for (const char* key : {"mold", "mold_hash", "config"})
        if (!meta.count(key)) throw io::InputError(db_path, 0, 0, key, "missing from the store: not a mold run to resume");
      if (!r.start.empty())
        throw io::InputError(db_path, 0, 0, "--start", "a resumed run keeps the layouts it started from: drop --start");
      mold_path = meta.at("mold");
      config_text = meta.at("config");
      start = stored_start(meta, db_path + ":start");
      // The run's polish budget is part of the run: a resume polishes as the run would have.
      if (meta.count("polish") && r.polish == 0) {
        try {
          polish_budget = std::stoi(meta.at("polish"));
        } catch (const std::exception&) {
          throw io::InputError(db_path, 0, 0, "polish", "not a whole number in the store's meta: " + meta.at("polish"));
        }
      }
      islands = meta.count("islands") ? IslandSettings::parse(meta.at("islands"), db_path + ":islands") : IslandSettings{};
      if (islands.islands == 0 && mpi_launch_size() > 0)
        throw io::InputError(db_path, 0, 0, "islands", "not an island run: resume it without mpirun");
      if (content_hash(read_file_text(mold_path)) != meta.at("mold_hash"))
        throw io::InputError(mold_path, 0, 0, "", "the mold spec changed since the run started; start a new run");
    }
    // A resumed run keeps its stored config; a new one resolves RUN.yaml and the command line.
    mold::MoldSpec spec = mold::load_mold_spec(mold_path);
    if (!resuming) {  // what is refused in milliseconds, before the model's seconds
      for (const std::string& given : r.start) (void)mold::read_layout(start_layout_path(given), spec);
      if (writer) check_out_free(db_path, out_dir);
    }
    made = resuming ? std::make_unique<const Session>(std::move(spec), config_text, db_path + ":config")
                    : std::make_unique<const Session>(std::move(spec), r.overrides);
    if (!resuming) start = start_genotypes(r.start, *made);
    // From here on the run writes: a signal stops it after a stored generation.
    if (r.on_ready) r.on_ready();
    if (!resuming && writer) {
      if (r.prepare_out) r.prepare_out(out_dir);
      check_out_free(db_path, out_dir);  // again: another run may have begun meanwhile
      auto meta = mold_run_meta(mold_path, *made);
      if (islands.islands > 0) meta["islands"] = islands.to_text();
      if (r.polish > 0) meta["polish"] = std::to_string(r.polish);
      if (!start.empty()) meta["start"] = start_text(start);
      for (std::size_t i = 0; i < r.start.size(); ++i) meta["start_layout_" + std::to_string(i)] = fs::absolute(r.start[i]).string();
      db = store::RunStore::create(db_path, meta);
    }
  };
  if (mpi_launch_size() == 0) {
    set_up();
  } else {
    std::exception_ptr failed;
    try {
      set_up();
    } catch (...) {
      failed = std::current_exception();
    }
    const bool ready = transport->all(!failed);
    if (failed) std::rethrow_exception(failed);
    if (!ready) return {out_dir, mold_path, false, 0, 0, 0};  // rank 0 says why
  }
  if (islands.islands == 0) transport.reset();  // a resumed run of one population
  const Session& session = *made;
  const mold::Scene& scene = session.scene();
  const std::vector<std::string>& names = session.objective_names();
  const RunConfig& config = session.config();
  const MoldProblem& problem = session.problem();
  const MoldOptimizer optimizer(problem, scene, config, start);
  spdlog::debug("mold {}: {} surface samples; run config:\n{}", mold_path, session.pipeline().surface_samples(),
                config.to_yaml(names));
  if (optimizer.pareto() && writer) spdlog::info(hypervolume_basis(optimizer, names));
  StoredRun stored;
  if (transport) {
    const ProgressPrinter printer(optimizer, config.log_every);
    stored = run_islands(optimizer, problem, islands, *transport, db ? &*db : nullptr,
                         [&](int index, const std::function<std::string()>& line) {
                           const int generation = optimizer.pareto() ? index / optimizer.mu() : index;
                           if (printer.prints(generation)) printer.print(generation, line());
                         },
                         stop);
    if (!writer) return {out_dir, mold_path, false, 0, 0, 0};  // rank 0 writes the outputs
  } else {
    stored = run_stored(optimizer, problem, *db, make_progress(optimizer, config.log_every), stop);
  }
  const opt::Generation& last = stored.last;

  // The best layout, for CAD and for re-scoring with mtcs evaluate; optionally polished.
  const opt::Individual& first = last.population.front();
  RunOutcome outcome{last, first.score, problem.genome(first.x), stored.seconds, mold_path, std::nullopt, first.score.value};
  outcome.interrupted = stored.interrupted;
  if (polish_budget > 0 && !stored.interrupted) {
    outcome.polished = polish(problem, scene, outcome.genome, polish_budget);
    if (outcome.polished->improved) {
      outcome.genome = outcome.polished->genome, outcome.best = outcome.polished->score;
      spdlog::info("polish (COBYLA, {} evaluations): objective {:.6g}", outcome.polished->evaluations, outcome.best.value);
    } else {  // an outcome, not a fault: --quiet keeps it off the screen (summary.json has it)
      spdlog::info("polish (COBYLA, {} evaluations) found nothing better than {:.6g}: {}", outcome.polished->evaluations,
                   outcome.best.value, outcome.polished->why_not);
    }
  }
  // What is written is rounded to the tolerance and tidied, and scored as written.
  outcome.genome = shop_layout(problem, scene, outcome.genome);
  outcome.best = problem.evaluate(problem.encode(outcome.genome));
  outcome.evaluation = session.pipeline().evaluate(mold::decode(scene, outcome.genome));
  const mold::Layout layout = write_run_outputs(out_dir, scene, optimizer, names, config.es.seed, outcome);
  const std::size_t bores = layout.bores.size(), circuits = outcome.genome.circuits.size();
  spdlog::info("{} best layout: {} bore{} in {} circuit{}, objective {:.6g}, {} evaluations in {:.6g} s",
               outcome.best.feasible ? "feasible" : "INFEASIBLE", bores, bores == 1 ? "" : "s", circuits,
               circuits == 1 ? "" : "s", outcome.best.value, last.evaluations, stored.seconds);
  spdlog::info("results in {}/: best.layout.yaml (mtcs evaluate {} --layout {}/best.layout.yaml), bores.csv, holes.csv, "
               "bores.stl, summary.json, run.sqlite",
               out_dir, mold_path, out_dir);
  // Which rule the best breaks, with the element and the number (a circuit's too: its flow, drop or rise).
  const auto& broken = outcome.evaluation.violations;
  for (std::size_t k = 0; k < broken.size() && k < kViolationsShown; ++k)
    spdlog::warn("best layout: {}", eval::violation_text(broken[k]));
  if (broken.size() > kViolationsShown)
    spdlog::warn("best layout: {} more violations in summary.json", broken.size() - kViolationsShown);
  for (const std::string& w : front_warnings(optimizer, last)) spdlog::warn(w);
  return {out_dir, mold_path, stored.interrupted, last.index, last.evaluations, optimizer.budget()};
}

}  // namespace mtcs::run
