#include "mtcs/eval/thermal_tiers.h"

#include <memory>

#include <tbb/enumerable_thread_specific.h>

#include "mtcs/thermal/finite_volume.h"
#include "mtcs/thermal/line_sinks.h"
#include "mtcs/thermal/void_plane.h"

namespace mtcs::eval {

thermal::Tier line_sink_tier(mold::ThermalTier tier) {
  switch (tier) {
    case mold::ThermalTier::T1: return thermal::Tier::T1;
    case mold::ThermalTier::T2: return thermal::Tier::T2;
    default: return thermal::Tier::T2d;
  }
}

namespace {

// The model and its per-thread caches live as long as the solver (shared by its copies).
struct LineSinks {
  LineSinks(const thermal::Setting& setting, const thermal::Samples& samples, const thermal::LineSinkOptions& options)
      : model(setting, samples, options) {}
  thermal::LineSinkModel model;
  tbb::enumerable_thread_specific<thermal::LineSinkCache> caches;
};

}  // namespace

TemperatureSolverFactory temperature_solver(mold::ThermalTier tier) {
  if (tier == mold::ThermalTier::Fd)
    return [](const thermal::Setting& setting, const thermal::Samples& samples, const mold::ThermalSpec& spec) {
      thermal::FvOptions options;
      options.cell = spec.cell_size;
      return TemperatureSolver([&setting, &samples, options](const std::vector<thermal::Channel>& channels) {
        thermal::FvResult r = thermal::solve_finite_volume({setting, channels}, samples, options);
        return SolvedTemperatures{std::move(r.temperature), std::move(r.heat_to_channel)};
      });
    };
  return [tier](const thermal::Setting& setting, const thermal::Samples& samples, const mold::ThermalSpec& spec) {
    thermal::LineSinkOptions options;
    options.tier = line_sink_tier(tier);
    options.elements = spec.elements_per_bore;
    options.images = spec.wall_images;
    options.void_panel = spec.void_panel;
    // thermal.cavity_void: plane: the line sinks in the block cut at the void (no cut: as is).
    const thermal::CavityCut cut = spec.void_plane ? thermal::cut_at_cavity_void(setting) : thermal::CavityCut{setting};
    auto sinks = std::make_shared<LineSinks>(cut.setting, samples, options);
    return TemperatureSolver([sinks, cut](const std::vector<thermal::Channel>& channels) {
      thermal::LineSinkSolution r = sinks->model.solve(cut.fold(channels), sinks->caches.local());
      return SolvedTemperatures{std::move(r.temperature), cut.unfold_heat(channels, r.channel_heat)};
    });
  };
}

}  // namespace mtcs::eval
