// The page's data (what report.js reads), from the run store through the run's own session:
//   title, run {dir, mold, algorithm, seed, evaluations, seconds, program}
//   objectives [{name, unit, scale}]
//   scene (scene_json.h), generation, shown (the member loaded first), best (the rank of the
//   generation's best: best.layout.yaml's for the last; SMS-EMOA's need not be 0)
//   members [{rank, objectives, value, feasible, violation, front, layout (layout_json.h),
//             violations, coolant (layout_json.h: per circuit, each bore's coolant in/out),
//             design_rules (eval/design_rules.h: each bore's depth and pitch in diameters)}]
//   convergence (convergence.h)
//   anytime {generation, evaluations, seconds, best_feasible, best_so_far, hypervolume,
//            hypervolume_so_far, ref} (convergence.h; replay's anytime.csv)
//   temperature {member, tier, unit, mesh, values (base64 float32 per vertex), min, max, mean,
//                std, hottest} or null
//   drilling_maps {member, part, grid, voxel_size, solid_voxels, rows, cols, seconds,
//                  entries [{bore, entry, direction, radius, length, inside, free, cell,
//                            direction_free, map (base64 bytes, rows x cols, 1 = blocked)}]}
//                 or null (no cavity with volume)

#include "mtcs/report/run_report.h"


#include <cmath>
#include <filesystem>
#include <limits>

#include "convergence.h"
#include "layout_json.h"
#include "base64.h"
#include "mtcs/report/drilling_maps.h"
#include "mtcs/eval/cavity_temperature.h"
#include "mtcs/eval/design_rules.h"
#include "mtcs/io/input_error.h"
#include "mtcs/opt/sms_emoa.h"
#include "mtcs/report/html_page.h"
#include "mtcs/run/run_record.h"
#include "mtcs/run/session.h"
#include "mtcs/run/stored_run.h"
#include "mtcs/store/run_store.h"
#include "scene_json.h"
#include "shop_member.h"

namespace mtcs::report {
namespace {

namespace fs = std::filesystem;

std::string objective_unit(const std::string& name) {
  if (name == "uniformity" || name == "worst_covered") return "mm";
  if (name == "temperature_mean" || name == "temperature_max") return "\u00b0C";
  if (name == "temperature_std" || name == "temperature_difference" || name == "temperature_std_side") return "K";
  if (name == "cycle_time") return "s";
  if (name == "cost_per_part") return "per part";
  return "";  // cost: the spec's cost units
}

// The field on the cavity surface refined to about 30 edges across the part: enough to show
// the hot spots, ~5 000 vertices (a few seconds of line sinks, ~150 kB in the page). A vertex
// where the model is singular (the corners of a heat-flux patch give +-inf) is sent as NaN and
// counted in `singular`; the page greys it.
Json temperature_json(const mold::Scene& scene, const mold::Layout& layout, int member) {
  const mold::Cavity& cavity = *scene.spec().cavity;
  const geometry::Box b = cavity.bounds();
  const double edge = std::max(cavity.sample_spacing / 2, (b.max - b.min).norm() / 30);
  const eval::CavityTemperature t = eval::cavity_temperature(scene, layout, eval::thermal_query(scene.spec()), {}, edge);
  std::vector<float> values;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  int singular = 0;
  for (const double v : t.field.values) {
    const bool finite = std::isfinite(v);
    values.push_back(finite ? float(v) : std::numeric_limits<float>::quiet_NaN());
    singular += !finite;
    if (finite) lo = std::min(lo, v), hi = std::max(hi, v);
  }
  return {{"member", member},        {"tier", t.tier},          {"unit", "\u00b0C"},
          {"mesh", mesh_json(t.field.surface)}, {"values", base64_floats(values)}, {"singular", singular}, {"min", lo},
          {"max", hi},               {"mean", t.summary.mean},  {"std", t.summary.std},
          {"hottest", vec_json(t.hottest)}, {"seconds", t.seconds}};
}

// The shown layout's drilling maps: phi (from +z) down the rows, gamma (about z) across.
Json drilling_maps_json(const DrillingMaps& maps, int member) {
  Json entries = Json::array();
  for (const EntryMap& e : maps.entries)
    entries.push_back({{"bore", e.bore},
                       {"entry", vec_json(e.entry)},
                       {"direction", vec_json(e.direction)},
                       {"radius", e.radius},
                       {"length", e.length},
                       {"inside", e.pivot_inside},
                       {"free", e.free_cells},
                       {"cell", e.cell},
                       {"direction_free", e.direction_free},
                       {"map", base64(e.cells.data(), e.cells.size())}});
  return {{"member", member},         {"part", maps.part},          {"grid", maps.grid},
          {"voxel_size", maps.voxel_size}, {"solid_voxels", maps.solid_voxels}, {"rows", maps.sphere.rows},
          {"cols", maps.sphere.cols}, {"seconds", maps.seconds},    {"entries", entries}};
}

}  // namespace

RunReport run_report(const std::string& run_dir, const ReportOptions& options) {
  const std::string db_path = (fs::path(run_dir) / "run.sqlite").string();
  if (!fs::exists(db_path)) throw io::InputError(db_path, 0, 0, "", "no stored run here");
  const store::RunStore db = store::RunStore::open(db_path);
  const auto meta = db.meta();
  if (!meta.count("mold")) throw io::InputError(db_path, 0, 0, "", "a test-problem run: no mold to report on");
  RunReport report;
  const run::Session session(run::stored_mold_spec(meta, options.mold, &report.note), meta.at("config"), db_path + ":config");
  const mold::Scene& scene = session.scene();
  const auto& names = session.objective_names();

  const auto summaries = db.summaries();
  if (summaries.empty()) throw io::InputError(db_path, 0, 0, "generation", "the run stored no generation yet");
  report.generation = options.generation.value_or(summaries.back().index);
  const auto generation = db.generation(report.generation);
  if (!generation) throw io::InputError(db_path, 0, 0, "--generation", "no stored generation " + std::to_string(report.generation));
  const auto& population = generation->population;
  const std::size_t best = run::best_rank(*generation, session.problem());
  report.member = options.member.value_or(int(best));
  if (report.member < 0 || std::size_t(report.member) >= population.size())
    throw io::InputError(db_path, 0, 0, "--member",
                         "generation " + std::to_string(report.generation) + " has members 0.." + std::to_string(population.size() - 1));

  Json data;
  const std::string mold_name = fs::path(meta.at("mold")).filename().string();
  data["title"] = "mtcs report: " + mold_name;
  data["run"] = {{"dir", fs::absolute(run_dir).lexically_normal().string()}, {"mold", meta.at("mold")},
                 {"algorithm", session.config().algorithm}, {"seed", meta.count("seed") ? meta.at("seed") : ""},
                 {"evaluations", summaries.back().evaluations}, {"seconds", summaries.back().seconds},
                 {"program", meta.count("program") ? meta.at("program") : ""}};
  data["objectives"] = Json::array();
  for (const auto& name : names) {
    const auto o = mold::objective_named(name);
    data["objectives"].push_back({{"name", name}, {"unit", objective_unit(name)}, {"scale", o ? session.spec().objectives.scale(*o) : 1.0}});
  }
  data["units"] = session.spec().units;
  data["scene"] = scene_json(session.spec());
  data["generation"] = report.generation;
  data["evaluations"] = generation->evaluations;
  data["shown"] = report.member;
  data["best"] = best;

  // Every member as the shop receives it (rounded, tidied, re-scored): the best is optimize's
  // best.layout.yaml and bores.csv, the front members replay's layouts; the front of those scores.
  std::vector<ShopMember> shop;
  opt::Generation rounded = *generation;
  for (std::size_t r = 0; r < population.size(); ++r) shop.push_back(shop_member(session, population[r].x));
  // The last generation's best as optimize wrote it: polished, when it was.
  if (report.generation == summaries.back().index)
    if (auto polished = polished_best(run_dir, session, report.note)) shop[best] = std::move(*polished);
  data["run"]["note"] = report.note;  // with what the polished best adds
  for (std::size_t r = 0; r < population.size(); ++r) rounded.population[r].score = shop[r].score;
  const auto front = opt::SmsEmoa::front(rounded);
  report.front = front.size();
  data["members"] = Json::array();
  mold::Layout shown;
  for (std::size_t r = 0; r < population.size(); ++r) {
    const opt::Score& score = shop[r].score;
    const eval::Evaluation e = session.pipeline().evaluate(shop[r].layout);
    const bool on_front = score.feasible && std::find(front.begin(), front.end(), score.objectives) != front.end();
    data["members"].push_back({{"rank", r},
                               {"objectives", score.objectives},
                               {"value", score.value},
                               {"feasible", score.feasible},
                               {"violation", score.violation},
                               {"front", on_front},
                               {"layout", layout_json(shop[r].plan)},
                               {"violations", violations_json(e.violations)},
                               {"coolant", coolant_json(shop[r].layout, session.spec(), e.bore_heat)},
                               {"design_rules", Json::parse(eval::design_rules_json_text(eval::design_rules(scene, shop[r].layout)))}});
    if (int(r) == report.member) shown = shop[r].layout;
  }
  report.members = population.size();
  report.bores = shown.bores.size();
  const run::MoldOptimizer optimizer(session.problem(), scene, session.config(), run::stored_start(meta, db_path + ":start"));
  const run::AnytimeTrace anytime = run::stored_anytime(optimizer, db);
  data["anytime"] = anytime_json(anytime);
  data["convergence"] = convergence_json(db, session.spec(), names, session.problem(), anytime.reference());
  report.generations = summaries.size();
  data["temperature"] = nullptr;
  if (options.temperature && session.spec().cavity) {
    data["temperature"] = temperature_json(scene, shown, report.member);
    report.temperature = true;
  }
  data["drilling_maps"] = nullptr;
  if (options.drilling_maps && has_drilling_part(session.spec())) {
    const DrillingMaps maps = drilling_maps(session.spec(), shown);
    data["drilling_maps"] = drilling_maps_json(maps, report.member);
    report.drilling_maps = maps.entries.size();
    report.drilling_seconds = maps.seconds;
  }
  report.html = html_page(data["title"].get<std::string>() + " (" + run_dir + ")", data.dump());
  return report;
}

}  // namespace mtcs::report
