#pragma once
// Everything a command needs to work on one mold, built once and in this order (DESIGN.md:
// spec -> Scene -> Pipeline -> RunConfig -> Problem): optimize, replay, compare-penalties,
// evaluate, interfere --layout and the benchmarks all start from a Session.

#include <memory>
#include <string>
#include <vector>

#include "mtcs/eval/pipeline.h"
#include "mtcs/mold/genome.h"
#include "mtcs/mold/scene.h"
#include "mtcs/run/mold_problem.h"
#include "mtcs/run/mold_run.h"
#include "mtcs/run/run_config.h"

namespace mtcs::run {

class Session {
 public:
  // The mold spec at `mold_path`, with the run config RUN.yaml and the command line resolve to.
  // Throws io::InputError naming file and field.
  // `scope`: PipelineScope::constraints for a command that checks clearances only.
  explicit Session(const std::string& mold_path, const RunOverrides& overrides = {},
                   eval::PipelineScope scope = eval::PipelineScope::everything);
  // A stored run's config, exactly as stored (YAML text; `origin` names it in errors).
  Session(mold::MoldSpec spec, const std::string& config_yaml, const std::string& origin,
          eval::PipelineScope scope = eval::PipelineScope::everything);
  Session(mold::MoldSpec spec, const RunOverrides& overrides);
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  const mold::Scene& scene() const { return *scene_; }
  const mold::MoldSpec& spec() const { return scene_->spec(); }
  const eval::Pipeline& pipeline() const { return *pipeline_; }
  const std::vector<std::string>& objective_names() const { return names_; }
  const RunConfig& config() const { return config_; }
  // The mold problem of the config (its weights, mutation rates and penalty variant).
  const MoldProblem& problem() const { return *problem_; }

  // A user's layout file, read as written or refused (mold::read_layout); each change the
  // drilling plan makes to it (a snap, a diagonal step drilled as legs) is logged as a warning.
  mold::Genome read_layout(const std::string& layout_path) const;

  // Scenes built by Sessions in this process: compare-penalties builds one per run, however
  // many variants it compares (a test counts them).
  static long scenes_built();

 private:
  Session(mold::MoldSpec spec, const std::function<RunConfig(const std::vector<std::string>&)>& config_for,
          eval::PipelineScope scope = eval::PipelineScope::everything);

  std::unique_ptr<const mold::Scene> scene_;
  std::unique_ptr<const eval::Pipeline> pipeline_;
  std::vector<std::string> names_;
  RunConfig config_;
  std::unique_ptr<const mold::Scene> screen_scene_;        // a screen with samples of its own only
  std::unique_ptr<const eval::Pipeline> screen_pipeline_;  // multi-fidelity runs only
  std::unique_ptr<const MoldProblem> problem_;
};

}  // namespace mtcs::run
