#pragma once
// RUN.yaml: how to optimise (configs/*.yaml document every field). The resolved config is
// stored with the run, so that a resumed run uses exactly the same settings.

#include <optional>
#include <string>
#include <vector>

#include "mtcs/mold/mold_spec.h"
#include "mtcs/run/mold_problem.h"
#include "mtcs/opt/evolution_strategy.h"

namespace mtcs::run {

struct RunConfig {
  std::string algorithm = "es";  // or sms-emoa: a Pareto front over the mold's objectives
  opt::EsConfig es;              // es.mu, es.evaluations and es.seed serve SMS-EMOA too
  // The mold runs restart the ES after 200 stalled generations (configs/README.md, "es.restart");
  // opt's own default stays off.
  RunConfig() { es.restart_after = 200; }
  std::vector<double> ref;       // SMS-EMOA: reference point in scaled objectives (default 4 each)
  std::vector<double> weights;  // per objective, in the spec's order; empty: all 1
  MutationRates mutation;
  int log_every = 10;           // generations between log lines when not on a terminal
  // The constraint handling the layouts are ranked by; unset: the mold spec's penalty.variant.
  std::optional<mold::PenaltyVariant> penalty;
  // Multi-fidelity (configs/README.md, "fidelity"): offspring are screened by this tier and
  // es.survivors of them re-scored by the spec's tier; unset: no screening.
  std::optional<mold::ThermalTier> screen_tier;
  int screen_elements = 0;  // M of the screening tier; 0: the spec's elements_per_bore
  int screen_wall_images = 0;                  // the screen's thermal.wall_images; 0: the spec's
  std::optional<double> screen_sample_spacing;  // mm, the screen's thermal.sample_spacing; unset: the spec's
  double final_cell = 0;    // mm: the best layout re-scored by finite volumes (T3); 0: not

  std::string to_yaml(const std::vector<std::string>& objective_names) const;
};

// Throws io::InputError with file, line, column and field.
RunConfig load_run_config(const std::string& path, const std::vector<std::string>& objective_names);
RunConfig parse_run_config(const std::string& yaml_text, const std::string& origin,
                           const std::vector<std::string>& objective_names);
// The config a run store keeps (resume, replay, report): a key added since the store was made
// takes the value that repeats the run as it was made, not today's default (a store made before
// the ES's restart on stall has no es.restart_after: its run never restarted).
RunConfig parse_stored_run_config(const std::string& yaml_text, const std::string& origin,
                                  const std::vector<std::string>& objective_names);

}  // namespace mtcs::run
