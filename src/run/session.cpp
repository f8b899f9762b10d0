#include "mtcs/run/session.h"

#include <atomic>

#include <spdlog/spdlog.h>

#include "mtcs/eval/thermal_tiers.h"
#include "mtcs/mold/layout_io.h"

namespace mtcs::run {
namespace {

std::atomic<long> scenes{0};

// The pipeline that screens offspring: the config's tier (and elements per bore) in place of
// the spec's; the tier-0 stages are the same.
std::unique_ptr<const eval::Pipeline> screening_pipeline(const mold::Scene& scene, const RunConfig& config) {
  if (!config.screen_tier) return nullptr;
  const int elements = config.screen_elements;
  eval::TemperatureSolverFactory factory = [tier = eval::temperature_solver(*config.screen_tier), elements](
                                               const thermal::Setting& setting, const thermal::Samples& samples,
                                               const mold::ThermalSpec& spec) {
    mold::ThermalSpec screen = spec;
    if (elements > 0) screen.elements_per_bore = elements;
    return tier(setting, samples, screen);
  };
  return std::make_unique<const eval::Pipeline>(scene, factory);
}

}  // namespace

Session::Session(mold::MoldSpec spec, const std::function<RunConfig(const std::vector<std::string>&)>& config_for,
                 eval::PipelineScope scope)
    : scene_(std::make_unique<const mold::Scene>(std::move(spec))),
      pipeline_(std::make_unique<const eval::Pipeline>(*scene_, eval::TemperatureSolverFactory{}, scope)),
      names_(pipeline_->objective_names()),
      config_(config_for(names_)),
      screen_pipeline_(screening_pipeline(*scene_, config_)),
      problem_(std::make_unique<const MoldProblem>(*pipeline_, config_.weights, config_.mutation, config_.penalty,
                                                   screen_pipeline_.get())) {
  ++scenes;
}

Session::Session(const std::string& mold_path, const RunOverrides& overrides, eval::PipelineScope scope)
    : Session(
          mold::load_mold_spec(mold_path),
          [&](const std::vector<std::string>& names) { return resolve_run_config(overrides, names); }, scope) {}

Session::Session(mold::MoldSpec spec, const RunOverrides& overrides)
    : Session(std::move(spec), [&](const std::vector<std::string>& names) { return resolve_run_config(overrides, names); }) {}

Session::Session(mold::MoldSpec spec, const std::string& config_yaml, const std::string& origin,
                 eval::PipelineScope scope)
    : Session(
          std::move(spec),
          [&](const std::vector<std::string>& names) { return parse_stored_run_config(config_yaml, origin, names); },
          scope) {}

long Session::scenes_built() { return scenes; }

mold::Genome Session::read_layout(const std::string& layout_path) const {
  mold::WrittenLayout w = mold::read_layout(layout_path, spec());
  for (const mold::LayoutChange& c : w.changes) spdlog::warn("{}: {}", layout_path, c.what);
  return std::move(w.genome);
}

}  // namespace mtcs::run
