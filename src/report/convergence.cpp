#include "convergence.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "mtcs/opt/hypervolume.h"
#include "mtcs/opt/sms_emoa.h"
#include "mtcs/run/stored_run.h"

namespace mtcs::report {
namespace {

double median(std::vector<double> v) {
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  const std::size_t mid = v.size() / 2;
  std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(mid), v.end());
  if (v.size() % 2) return v[mid];
  return (v[mid] + *std::max_element(v.begin(), v.begin() + std::ptrdiff_t(mid))) / 2;
}

}  // namespace

Json convergence_json(const store::RunStore& db, const mold::MoldSpec& spec, const std::vector<std::string>& objectives,
                      const opt::Problem& problem, const std::vector<double>& scaled_ref) {
  std::vector<double> scale;
  for (const auto& name : objectives) {
    const auto o = mold::objective_named(name);
    scale.push_back(o ? spec.objectives.scale(*o) : 1.0);
  }
  const auto summaries = db.summaries();
  std::vector<std::vector<opt::Point>> fronts;
  std::vector<double> medians, bests;
  for (const auto& s : summaries) {
    const opt::Generation g = *db.generation(s.index);
    std::vector<double> values;
    for (const auto& ind : g.population) values.push_back(ind.score.value);
    medians.push_back(median(values));
    bests.push_back(values.empty() ? 0.0 : values[run::best_rank(g, problem)]);
    std::vector<opt::Point> front = opt::SmsEmoa::front(g);
    for (auto& p : front)
      for (std::size_t k = 0; k < p.size() && k < scale.size(); ++k) p[k] /= scale[k];
    fronts.push_back(std::move(front));
  }
  const opt::Point& ref = scaled_ref;
  Json out{{"generation", Json::array()}, {"evaluations", Json::array()}, {"seconds", Json::array()},
           {"best", Json::array()},       {"median", Json::array()},      {"feasible_share", Json::array()},
           {"hypervolume", Json::array()}, {"front_size", Json::array()}, {"hv_ref", ref}};
  for (std::size_t i = 0; i < summaries.size(); ++i) {
    const auto& s = summaries[i];
    out["generation"].push_back(s.index);
    out["evaluations"].push_back(s.evaluations);
    out["seconds"].push_back(s.seconds);
    out["best"].push_back(bests[i]);
    out["median"].push_back(medians[i]);
    out["feasible_share"].push_back(s.feasible_share);
    out["hypervolume"].push_back(fronts[i].empty() ? 0.0 : opt::hypervolume(fronts[i], ref));
    out["front_size"].push_back(fronts[i].size());
  }
  return out;
}

Json anytime_json(const run::AnytimeTrace& trace) {
  Json out{{"generation", Json::array()}, {"evaluations", Json::array()}, {"seconds", Json::array()},
           {"best_feasible", Json::array()}, {"best_so_far", Json::array()}, {"hypervolume", Json::array()},
           {"hypervolume_so_far", Json::array()}, {"ref", trace.reference()}};
  const auto finite_or_null = [](double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); };
  for (const run::AnytimeRow& r : trace.rows()) {
    out["generation"].push_back(r.generation);
    out["evaluations"].push_back(r.evaluations);
    out["seconds"].push_back(r.seconds);
    out["best_feasible"].push_back(finite_or_null(r.best_feasible));
    out["best_so_far"].push_back(finite_or_null(r.best_so_far));
    out["hypervolume"].push_back(r.hypervolume);
    out["hypervolume_so_far"].push_back(r.hypervolume_so_far);
  }
  return out;
}

}  // namespace mtcs::report
