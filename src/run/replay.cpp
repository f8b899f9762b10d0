#include "mtcs/run/replay.h"

#include <algorithm>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>

#include "mtcs/io/atomic_file.h"
#include "mtcs/mold/decoder.h"
#include "mtcs/mold/layout_io.h"
#include "mtcs/opt/sms_emoa.h"

namespace mtcs::run {
namespace {

namespace fs = std::filesystem;

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

}  // namespace

Replay replay_fronts(const store::RunStore& db, const Session& session, std::optional<int> generation,
                     const std::string& out_dir) {
  const mold::Scene& scene = session.scene();
  const std::vector<std::string>& names = session.objective_names();
  const MoldProblem& problem = session.problem();
  std::vector<int> indices;
  const auto summaries = db.summaries();
  for (const auto& s : summaries)
    if (!generation || s.index == *generation) indices.push_back(s.index);
  if (indices.empty()) return {};
  const fs::path out = out_dir;
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
  return {long(indices.size()), checked, mismatches};
}

}  // namespace mtcs::run
