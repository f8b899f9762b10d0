#include "mtcs/run/session.h"

#include <atomic>

namespace mtcs::run {
namespace {

std::atomic<long> scenes{0};

}  // namespace

Session::Session(mold::MoldSpec spec, const std::function<RunConfig(const std::vector<std::string>&)>& config_for)
    : scene_(std::make_unique<const mold::Scene>(std::move(spec))),
      pipeline_(std::make_unique<const eval::Pipeline>(*scene_)),
      names_(pipeline_->objective_names()),
      config_(config_for(names_)),
      problem_(std::make_unique<const MoldProblem>(*pipeline_, config_.weights, config_.mutation, config_.penalty)) {
  ++scenes;
}

Session::Session(const std::string& mold_path, const RunOverrides& overrides)
    : Session(mold::load_mold_spec(mold_path), overrides) {}

Session::Session(mold::MoldSpec spec, const RunOverrides& overrides)
    : Session(std::move(spec), [&](const std::vector<std::string>& names) { return resolve_run_config(overrides, names); }) {}

Session::Session(mold::MoldSpec spec, const std::string& config_yaml, const std::string& origin)
    : Session(std::move(spec),
              [&](const std::vector<std::string>& names) { return parse_run_config(config_yaml, origin, names); }) {}

long Session::scenes_built() { return scenes; }

}  // namespace mtcs::run
