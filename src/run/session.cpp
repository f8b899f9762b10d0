#include "mtcs/run/session.h"

#include <algorithm>
#include <atomic>
#include <chrono>

#include <spdlog/spdlog.h>

#include "mtcs/eval/thermal_tiers.h"
#include "mtcs/mold/layout_io.h"

namespace mtcs::run {
namespace {

std::atomic<long> scenes{0};

// The scene a screen with samples of its own sees: the spec with the screen's
// thermal.sample_spacing (never finer than the cavity's samples, as the spec's own); none when
// the screen takes the spec's samples.
std::unique_ptr<const mold::Scene> screening_scene(const mold::Scene& scene, const RunConfig& config) {
  if (!config.screen_tier || !config.screen_sample_spacing) return nullptr;
  mold::MoldSpec spec = scene.spec();
  spec.thermal.sample_spacing =
      spec.cavity ? std::max(*config.screen_sample_spacing, spec.cavity->sample_spacing) : *config.screen_sample_spacing;
  return std::make_unique<const mold::Scene>(std::move(spec));
}

// The pipeline that screens offspring: the config's tier (elements per bore, wall images) in
// place of the spec's; the tier-0 stages are the same.
std::unique_ptr<const eval::Pipeline> screening_pipeline(const mold::Scene& scene, const RunConfig& config) {
  if (!config.screen_tier) return nullptr;
  const int elements = config.screen_elements, images = config.screen_wall_images;
  eval::TemperatureSolverFactory factory = [tier = eval::temperature_solver(*config.screen_tier), elements, images](
                                               const thermal::Setting& setting, const thermal::Samples& samples,
                                               const mold::ThermalSpec& spec) {
    mold::ThermalSpec screen = spec;
    if (elements > 0) screen.elements_per_bore = elements;
    if (images > 0) screen.wall_images = images;
    return tier(setting, samples, screen);
  };
  return std::make_unique<const eval::Pipeline>(scene, factory);
}

// The scene's pipeline. A part's void makes the thermal model a matter of seconds (its panels
// solved once): said before, and how long it took after, so that a run does not start silent.
std::unique_ptr<const eval::Pipeline> built_pipeline(const mold::Scene& scene, eval::PipelineScope scope) {
  const mold::MoldSpec& spec = scene.spec();
  const bool slow = scope == eval::PipelineScope::everything && spec.thermal.void_panel > 0 &&
                    std::any_of(spec.objectives.use.begin(), spec.objectives.use.end(), mold::is_temperature_objective);
  if (slow)
    spdlog::info("thermal model ({}): the part's void as panels of {} mm, solved once", mold::to_string(spec.thermal.tier),
                 spec.thermal.void_panel);
  const auto t0 = std::chrono::steady_clock::now();
  auto pipeline = std::make_unique<const eval::Pipeline>(scene, eval::TemperatureSolverFactory{}, scope);
  if (slow)
    spdlog::info("thermal model ready in {:.1f} s",
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  return pipeline;
}

}  // namespace

Session::Session(mold::MoldSpec spec, const std::function<RunConfig(const std::vector<std::string>&)>& config_for,
                 eval::PipelineScope scope)
    : scene_(std::make_unique<const mold::Scene>(std::move(spec))),
      pipeline_(built_pipeline(*scene_, scope)),
      names_(pipeline_->objective_names()),
      config_(config_for(names_)),
      screen_scene_(screening_scene(*scene_, config_)),
      screen_pipeline_(screening_pipeline(screen_scene_ ? *screen_scene_ : *scene_, config_)),
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
