#include "mtcs/run/replay.h"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>

#include <algorithm>
#include <limits>
#include <nlohmann/json.hpp>

#include "mtcs/io/atomic_file.h"
#include "mtcs/io/input_error.h"
#include "mtcs/mold/decoder.h"
#include "mtcs/mold/layout_io.h"
#include "mtcs/opt/sms_emoa.h"
#include "mtcs/run/anytime_trace.h"
#include "mtcs/run/run_record.h"
#include "mtcs/run/shop_layout.h"

namespace mtcs::run {

namespace fs = std::filesystem;

namespace {

// Per objective, [lowest, highest] over the feasible fronts of the replayed generations: the
// axes of every plot, so that an animation of them holds still.
nlohmann::ordered_json front_limits(const std::vector<opt::Generation>& generations, std::size_t objectives) {
  std::vector<std::pair<double, double>> limits(objectives, {std::numeric_limits<double>::infinity(),
                                                             -std::numeric_limits<double>::infinity()});
  for (const auto& g : generations)
    for (const auto& p : opt::SmsEmoa::front(g))
      for (std::size_t k = 0; k < objectives && k < p.size(); ++k)
        limits[k] = {std::min(limits[k].first, p[k]), std::max(limits[k].second, p[k])};
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const auto& [lo, hi] : limits) out.push_back(lo <= hi ? nlohmann::ordered_json{lo, hi} : nlohmann::ordered_json{0, 1});
  return out;
}

// A folder that takes the place of `target` on commit, and is removed if never committed.
class StagedFolder {
 public:
  explicit StagedFolder(fs::path target)
      : target_(std::move(target)),
        staged_(target_.parent_path() / ("." + target_.filename().string() + ".tmp-" + std::to_string(::getpid()))) {
    remove_abandoned();
    fs::remove_all(staged_);
    fs::create_directories(staged_);
  }
  ~StagedFolder() {
    std::error_code ec;
    if (!committed_) fs::remove_all(staged_, ec);
  }
  const fs::path& path() const { return staged_; }
  void commit() {
    // The previous folder steps aside first: a rename cannot replace a non-empty folder.
    const fs::path old = target_.parent_path() / ("." + target_.filename().string() + ".old-" + std::to_string(::getpid()));
    if (fs::exists(target_)) fs::rename(target_, old);
    fs::rename(staged_, target_);
    committed_ = true;
    std::error_code ec;
    fs::remove_all(old, ec);
  }

 private:
  // What a replay killed with -9 left: staged or set-aside folders of processes that are gone.
  void remove_abandoned() const {
    const std::string stem = "." + target_.filename().string() + ".";
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(target_.parent_path(), ec)) {
      const std::string name = entry.path().filename().string();
      if (name.rfind(stem, 0) != 0) continue;
      const std::size_t dash = name.rfind('-');
      if (dash == std::string::npos || name.find_first_not_of("0123456789", dash + 1) != std::string::npos) continue;
      const long pid = std::atol(name.c_str() + dash + 1);
      if (pid > 0 && ::kill(pid_t(pid), 0) != 0 && errno == ESRCH) fs::remove_all(entry.path(), ec);
    }
  }

  fs::path target_, staged_;
  bool committed_ = false;
};

// A generation's feasible non-dominated members, one per point of the front (the best ranked of
// equal ones): front_G.csv and the JSON list of them.
nlohmann::ordered_json write_front(const opt::Generation& g, const std::vector<std::string>& names, const fs::path& out) {
  nlohmann::ordered_json front = nlohmann::ordered_json::array();
  io::AtomicFile csv((out / ("front_" + std::to_string(g.index) + ".csv")).string());
  csv.stream() << "rank";
  for (const auto& n : names) csv.stream() << ',' << n;
  csv.stream() << '\n';
  auto points = opt::SmsEmoa::front(g);
  for (std::size_t r = 0; r < g.population.size(); ++r) {
    const auto& ind = g.population[r];
    const auto point = std::find(points.begin(), points.end(), ind.score.objectives);
    if (!ind.score.feasible || point == points.end()) continue;
    points.erase(point);  // listed: its equals further down are not
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
  io::AtomicFile json((out / ("front_" + std::to_string(g.index) + ".json")).string());
  json.stream() << nlohmann::ordered_json{{"generation", g.index}, {"evaluations", g.evaluations}, {"front", front}}.dump(2)
                << '\n';
  json.commit();
  return front;
}

}  // namespace

std::vector<int> replayed_generations(const std::vector<int>& stored, const ReplayChoice& choice,
                                      const std::string& db_path) {
  if (choice.generation) {
    if (std::find(stored.begin(), stored.end(), *choice.generation) == stored.end())
      throw io::InputError(db_path, 0, 0, "generation", "no such stored generation");
    return {*choice.generation};
  }
  if (stored.empty()) throw io::InputError(db_path, 0, 0, "generation", "no stored generation");
  const std::size_t n = stored.size();
  const std::size_t every =
      choice.all ? 1 : choice.every > 0 ? std::size_t(choice.every) : (n + kReplaySample - 1) / std::size_t(kReplaySample);
  std::vector<int> out;
  for (std::size_t i = 0; i < n; i += every) out.push_back(stored[i]);
  if (out.back() != stored.back()) out.push_back(stored.back());
  return out;
}

ReplayResult write_replay(const Session& session, const store::RunStore& db, const std::string& dir,
                          const ReplayChoice& choice, const std::function<void(const fs::path&)>& before_commit) {
  const std::string db_path = (fs::path(dir) / "run.sqlite").string();
  const std::vector<std::string>& names = session.objective_names();
  const MoldProblem& problem = session.problem();
  std::vector<int> stored;
  const std::vector<store::GenerationSummary> summaries = db.summaries();
  for (const auto& s : summaries) stored.push_back(s.index);
  // Anytime behaviour over every stored generation (a --generation replay: that one only).
  const MoldOptimizer optimizer(problem, session.scene(), session.config(), stored_start(db.meta(), db_path + ":start"));
  AnytimeTrace anytime(optimizer);
  const std::vector<int> indices = replayed_generations(stored, choice, db_path);

  ReplayResult result;
  result.folder = fs::path(dir) / "replay";
  std::vector<opt::Generation> kept;
  // Every stored generation is re-evaluated (or the one asked for); the sample is kept for files.
  for (std::size_t i = 0; i < stored.size(); ++i) {
    const int index = stored[i];
    if (choice.generation && index != *choice.generation) continue;
    opt::Generation g = *db.generation(index);
    anytime.add(g, summaries[i]);
    for (const auto& ind : g.population) {
      const opt::Score again = problem.evaluate(ind.x);
      ++result.checked;
      if (again.objectives != ind.score.objectives || again.violation != ind.score.violation) ++result.mismatches;
    }
    if (std::binary_search(indices.begin(), indices.end(), index)) kept.push_back(std::move(g));
  }

  StagedFolder folder(result.folder);
  const fs::path& out = folder.path();
  // The plots: one PNG per replayed generation, numbered by generation with the width of the
  // run's largest index (so that they sort), and axes that fit every replayed front.
  const std::size_t width = std::max<std::size_t>(4, std::to_string(stored.back()).size());
  nlohmann::ordered_json frames{{"objectives", names}, {"limits", front_limits(kept, names.size())},
                                {"frames", nlohmann::ordered_json::array()}};
  nlohmann::ordered_json front;
  for (const opt::Generation& g : kept) {
    front = write_front(g, names, out);
    std::string number = std::to_string(g.index);
    number.insert(0, width - std::min(width, number.size()), '0');
    frames["frames"].push_back({{"generation", g.index},
                                {"evaluations", g.evaluations},
                                {"front", "front_" + std::to_string(g.index) + ".json"},
                                {"png", "front_" + number + ".png"}});
  }
  // The layouts of the last replayed front, for CAD and re-scoring: one STL per member.
  const opt::Generation& last = kept.back();
  for (const auto& m : front) {
    const int r = m["rank"];
    const mold::Genome genome = shop_layout(problem, session.scene(), problem.genome(last.population[std::size_t(r)].x));
    const mold::Layout layout = shop_plan(mold::decode(session.scene(), genome));
    const std::string stem = "front_" + std::to_string(last.index) + "_rank" + std::to_string(r);
    mold::save_layout((out / (stem + ".layout.yaml")).string(), genome);
    mold::save_bores_csv((out / (stem + ".bores.csv")).string(), layout);
    mold::save_bores_stl((out / (stem + ".bores.stl")).string(), layout);
  }
  anytime.write_csv((out / "anytime.csv").string());
  frames["anytime"] = "anytime.csv";  // for the plots and the report
  io::AtomicFile frames_file((out / "frames.json").string());
  frames_file.stream() << frames.dump(1) << '\n';
  frames_file.commit();
  if (before_commit) before_commit(out);
  folder.commit();
  result.generations = kept.size();
  return result;
}

}  // namespace mtcs::run
