#include "mtcs/run/mold_run.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "mtcs/io/input_error.h"
#include "mtcs/opt/population.h"
#include "mtcs/opt/sms_emoa.h"

namespace mtcs::run {

RunConfig resolve_run_config(const RunOverrides& o, const std::vector<std::string>& names) {
  RunConfig config;
  if (!o.config.empty()) config = load_run_config(o.config, names);
  if (!o.algorithm.empty()) config.algorithm = o.algorithm;
  if (!o.ref.empty()) {
    if (o.ref.size() != names.size())
      throw io::InputError("", 0, 0, "--ref", "needs one value per objective (" + std::to_string(names.size()) + ")");
    for (const double r : o.ref)
      if (!(r > 0)) throw io::InputError("", 0, 0, "--ref", "values must be positive (scaled objectives)");
    config.ref = o.ref;
  }
  if (o.seed) config.es.seed = *o.seed;
  if (o.evaluations) config.es.evaluations = *o.evaluations;
  return config;
}

std::vector<double> scaled_reference(const RunConfig& config, const MoldProblem& problem, const mold::Objectives& obj,
                                     const std::vector<opt::Genotype>& start) {
  if (!config.ref.empty()) return config.ref;
  std::vector<double> scales;
  for (const auto o : obj.use) scales.push_back(obj.scale(o));
  return scaled_reference_of(opt::sample_population(problem, config.es.seed, config.es.mu, start), scales);
}

std::vector<double> scaled_reference_of(const opt::Generation& initial, const std::vector<double>& scales) {
  std::vector<double> worst(scales.size(), -std::numeric_limits<double>::infinity());
  for (const auto& ind : initial.population)
    for (std::size_t k = 0; k < worst.size() && k < ind.score.objectives.size(); ++k)
      if (std::isfinite(ind.score.objectives[k])) worst[k] = std::max(worst[k], ind.score.objectives[k] / scales[k]);
  std::vector<double> ref;
  for (const double w : worst) ref.push_back(std::isfinite(w) && w > 0 ? 2 * w : 4.0);
  return ref;
}

std::string reference_origin(const RunConfig& config) {
  if (!config.ref.empty()) return "given (--ref or the run config's ref)";
  return "twice the worst value of each objective in the initial population (seed " + std::to_string(config.es.seed) +
         ", " + std::to_string(config.es.mu) + " layouts)";
}

opt::EsConfig MoldOptimizer::es_config(const mold::Scene& scene, const RunConfig& config,
                                       const std::vector<opt::Genotype>& start) {
  opt::EsConfig c = config.es;
  c.start = start;
  // Waypoint moves finer than a tenth of the smallest drill change nothing that matters.
  const auto& d = scene.spec().drilling.diameters;
  c.min_step = 0.1 * *std::min_element(d.begin(), d.end());
  return c;
}

opt::SmsConfig MoldOptimizer::sms_config(const MoldProblem& problem, const mold::Scene& scene, const RunConfig& config,
                                         const std::vector<opt::Genotype>& start) {
  opt::SmsConfig c;
  c.start = start;
  c.mu = config.es.mu;
  c.evaluations = config.es.evaluations;
  c.seed = config.es.seed;
  // The reference point in raw units, from the scaled one of the config.
  const auto& obj = scene.spec().objectives;
  // Only SMS-EMOA needs it: the ES's runs evaluate no extra population.
  const std::vector<double> scaled = config.algorithm == "sms-emoa" ? run::scaled_reference(config, problem, obj, start)
                                     : config.ref.empty() ? std::vector<double>(obj.use.size(), 4.0) : config.ref;
  for (std::size_t k = 0; k < obj.use.size(); ++k) c.ref.push_back(scaled[k] * obj.scale(obj.use[k]));
  return c;
}

MoldOptimizer::MoldOptimizer(const MoldProblem& problem, const mold::Scene& scene, const RunConfig& config,
                             const std::vector<opt::Genotype>& start)
    : es_(problem, es_config(scene, config, start)), sms_(problem, sms_config(problem, scene, config, start)),
      pareto_(config.algorithm == "sms-emoa"), final_cell_(config.final_cell),
      reference_origin_(run::reference_origin(config)), reference_from_first_generation_(!pareto_ && config.ref.empty()) {
  const auto& obj = scene.spec().objectives;
  for (const auto o : obj.use) scales_.push_back(obj.scale(o));
}

std::vector<double> MoldOptimizer::scaled_reference() const {
  std::vector<double> r = raw_reference();
  for (std::size_t k = 0; k < r.size(); ++k) r[k] /= scales_[k];
  return r;
}

double MoldOptimizer::scaled_hypervolume(const std::vector<opt::Point>& raw_front) const {
  return scaled_hypervolume(raw_front, scaled_reference());
}

double MoldOptimizer::scaled_hypervolume(const std::vector<opt::Point>& raw_front, const std::vector<double>& scaled_ref) const {
  std::vector<opt::Point> front = raw_front;
  for (auto& p : front)
    for (std::size_t k = 0; k < p.size(); ++k) p[k] /= scales_[k];
  return opt::hypervolume(front, scaled_ref);
}

opt::Generation MoldOptimizer::run(const opt::Generation* start,
                                   const std::function<void(const opt::Generation&)>& on_generation,
                                   const std::function<bool()>& stop) const {
  std::function<bool(const opt::Generation&)> at_generation_end;
  if (stop)
    at_generation_end = [&](const opt::Generation& g) { return (!pareto_ || g.index % mu() == 0) && stop(); };
  return pareto_ ? opt::run(sms_, start, on_generation, at_generation_end)
                 : opt::run(es_, start, on_generation, at_generation_end);
}

}  // namespace mtcs::run
