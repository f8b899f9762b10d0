#include "mtcs/run/mold_run.h"

#include <algorithm>

#include "mtcs/io/input_error.h"

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

std::vector<double> scaled_reference(const RunConfig& config, std::size_t objectives) {
  return config.ref.empty() ? std::vector<double>(objectives, 4.0) : config.ref;
}

opt::EsConfig MoldOptimizer::es_config(const mold::Scene& scene, const RunConfig& config) {
  opt::EsConfig c = config.es;
  // Waypoint moves finer than a tenth of the smallest drill change nothing that matters.
  const auto& d = scene.spec().drilling.diameters;
  c.min_step = 0.1 * *std::min_element(d.begin(), d.end());
  return c;
}

opt::SmsConfig MoldOptimizer::sms_config(const mold::Scene& scene, const RunConfig& config) {
  opt::SmsConfig c;
  c.mu = config.es.mu;
  c.evaluations = config.es.evaluations;
  c.seed = config.es.seed;
  // The reference point in raw units, from the scaled one of the config.
  const auto& obj = scene.spec().objectives;
  const std::vector<double> scaled = scaled_reference(config, obj.use.size());
  for (std::size_t k = 0; k < obj.use.size(); ++k) c.ref.push_back(scaled[k] * obj.scale(obj.use[k]));
  return c;
}

MoldOptimizer::MoldOptimizer(const MoldProblem& problem, const mold::Scene& scene, const RunConfig& config)
    : es_(problem, es_config(scene, config)), sms_(problem, sms_config(scene, config)),
      pareto_(config.algorithm == "sms-emoa"), final_cell_(config.final_cell) {}

opt::Generation MoldOptimizer::run(const opt::Generation* start,
                                   const std::function<void(const opt::Generation&)>& on_generation) const {
  return pareto_ ? opt::run(sms_, start, on_generation) : opt::run(es_, start, on_generation);
}

}  // namespace mtcs::run
