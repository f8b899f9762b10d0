#include "mtcs/run/run_outputs.h"

#include <filesystem>
#include <set>
#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>

#include "mtcs/eval/cavity_temperature.h"
#include "mtcs/eval/circuit_hydraulics.h"
#include "mtcs/eval/evaluation_report.h"

#include "mtcs/io/atomic_file.h"
#include "mtcs/io/number_text.h"
#include "mtcs/mold/decoder.h"
#include "mtcs/mold/layout_io.h"
#include "mtcs/opt/hypervolume.h"
#include "mtcs/opt/sms_emoa.h"
#include "mtcs/run/shop_layout.h"

namespace mtcs::run {

std::vector<std::string> front_warnings(const MoldOptimizer& optimizer, const opt::Generation& last) {
  if (!optimizer.pareto()) return {};
  const auto front = opt::SmsEmoa::front(last);
  std::vector<std::string> out;
  if (front.empty()) return {"no feasible layout in the final population: the front is empty"};
  if (optimizer.scaled_hypervolume(front) == 0)
    out.push_back("the front's hypervolume is 0: every point lies outside the reference point; give --ref r1,r2,... "
                  "(scaled objectives) beyond the front.csv values / their scales");
  if (std::set<opt::Point>(front.begin(), front.end()).size() == 1)
    out.push_back("the front collapsed to one design: try more --evaluations or a larger es.mu");
  return out;
}

mold::Layout write_run_outputs(const std::string& out_dir, const mold::Scene& scene, const MoldOptimizer& optimizer,
                               const std::vector<std::string>& names, std::uint64_t seed, const RunOutcome& o) {
  namespace fs = std::filesystem;
  const mold::Layout layout = mold::decode(scene, o.genome);
  const mold::Layout plan = shop_plan(layout, o.tolerance);
  mold::save_layout((fs::path(out_dir) / "best.layout.yaml").string(), o.genome);
  mold::save_bores_csv((fs::path(out_dir) / "bores.csv").string(), plan);
  mold::save_holes_csv((fs::path(out_dir) / "holes.csv").string(), plan);
  mold::save_bores_stl((fs::path(out_dir) / "bores.stl").string(), plan);
  nlohmann::ordered_json summary;
  summary["seed"] = seed;
  summary["evaluations"] = o.last.evaluations;
  summary["best_objective"] = o.best.value;
  summary["feasible"] = o.best.feasible;
  summary["seconds"] = o.seconds;
  summary["generations"] = o.last.index;
  summary["interrupted"] = o.interrupted;
  // Absolute, as the run store keeps it: a resumed run (which knows the path from the store) and a
  // new one (given it relative to the working folder) write the same.
  summary["mold"] = fs::absolute(o.mold_path).lexically_normal().string();
  summary["tolerance_mm"] = o.tolerance;  // coordinates in the layout and hole tables are rounded to it
  for (std::size_t k = 0; k < names.size() && k < o.best.objectives.size(); ++k)
    summary["objectives"][names[k]] = o.best.objectives[k];
  summary["violation"] = o.best.violation;
  summary["violations"] = nlohmann::ordered_json::array();
  for (const eval::Violation& v : o.evaluation.violations)
    summary["violations"].push_back({{"kind", eval::to_string(v.kind)}, {"elements", v.elements}, {"found", v.distance},
                                     {"needed", v.margin}, {"text", eval::violation_text(v)}});
  // Each circuit's flow, Reynolds number, drop, heat and rise (mtcs thermal --json's "coolant").
  if (const eval::CoolantCircuits cc = eval::coolant_circuits(layout, scene.spec(), o.evaluation.bore_heat); cc.flowing)
    summary["coolant"] = nlohmann::ordered_json::parse(eval::coolant_circuits_json_text(cc));
  if (optimizer.pareto()) {
    const auto front = opt::SmsEmoa::front(o.last);
    summary["algorithm"] = "sms-emoa";
    summary["front_size"] = front.size();
    // As every output gives it: in scaled objectives (objective / its scale), with that reference point.
    summary["hypervolume"] = optimizer.scaled_hypervolume(front);
    summary["reference_point"] = optimizer.scaled_reference();
    summary["reference_point_origin"] = optimizer.reference_origin();
    summary["warnings"] = front_warnings(optimizer, o.last);
    for (std::size_t k = 0; k < names.size(); ++k) summary["objective_scales"][names[k]] = optimizer.scales()[k];
    // front.csv: the final feasible non-dominated objective vectors, for plotting.
    io::AtomicFile csv((fs::path(out_dir) / "front.csv").string());
    for (std::size_t k = 0; k < names.size(); ++k) csv.stream() << (k ? "," : "") << names[k];
    csv.stream() << "\n";
    for (const auto& f : front) {
      for (std::size_t k = 0; k < f.size(); ++k) csv.stream() << (k ? "," : "") << io::shortest(f[k]);
      csv.stream() << "\n";
    }
    csv.commit();
  }
  if (optimizer.final_cell() > 0 && scene.spec().cavity) {
    // Multi-fidelity's last step: the best layout by the finite volumes, as `mtcs thermal
    // --tier fd --cell h` scores it.
    eval::ThermalQuery query = eval::thermal_query(scene.spec());
    query.tier = mold::ThermalTier::Fd;
    query.cell = optimizer.final_cell();
    const eval::CavityTemperature t3 = eval::cavity_temperature(scene, layout, query);
    summary["t3"] = {{"cell_mm", query.cell}, {"mean", t3.summary.mean}, {"std", t3.summary.std},
                     {"max", t3.summary.max}, {"seconds", t3.seconds}};
    spdlog::info("best layout by finite volumes (T3, cell {} mm, {:.3g} s): mean {:.4g} C, std {:.4g} K, max {:.4g} C",
                 query.cell, t3.seconds, t3.summary.mean, t3.summary.std, t3.summary.max);
  }
  if (o.polished)
    summary["polish"] = {{"evaluations", o.polished->evaluations}, {"improved", o.polished->improved},
                         {"before", o.before_polish}, {"after", o.polished->score.value}};
  if (o.polished && !o.polished->improved) summary["polish"]["why_not"] = o.polished->why_not;
  io::AtomicFile file((fs::path(out_dir) / "summary.json").string());
  file.stream() << summary.dump(2) << "\n";
  file.commit();
  return layout;
}

}  // namespace mtcs::run
