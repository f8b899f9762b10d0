#pragma once
// The temperature objectives (temperature_mean, temperature_std, temperature_max, cycle_time)
// from the cavity-surface temperatures a thermal tier computes, and the hook through which the
// pipeline asks a tier for them.

#include <functional>
#include <vector>

#include "mtcs/mold/mold_spec.h"
#include "mtcs/thermal/model.h"

namespace mtcs::eval {

// What a tier returns for one layout: the temperatures at the samples and the heat each channel
// carries away (the coolant's rise and the circuits' shop checks need it).
struct SolvedTemperatures {
  std::vector<double> temperature;   // degrees C at the samples (and any points after them)
  std::vector<double> channel_heat;  // W into each channel's coolant, in the channels' order;
                                     // empty when the solver does not say
};
// One layout's channels solved. Called from several threads at once: it must not change shared
// state.
using TemperatureSolver = std::function<SolvedTemperatures(const std::vector<thermal::Channel>& channels)>;
// Builds a scene's solver once, from what does not depend on the layout (precompute there).
// The setting and samples outlive the solver, which may keep references to them.
using TemperatureSolverFactory =
    std::function<TemperatureSolver(const thermal::Setting& setting, const thermal::Samples& samples,
                                    const mold::ThermalSpec& spec)>;

struct TemperatureObjectives {
  double mean = 0, std = 0, max = 0;  // degrees C, K, degrees C; area-weighted over the samples
  double min = 0;                     // degrees C: the coldest sample
  double cycle_time = 0;              // s: cooling_time at the hottest sample (coupled: plus
                                      // fill, pack and open, the whole cycle)
  geometry::Vec3 hottest = geometry::Vec3::Zero();  // mm: where max is
  geometry::Vec3 coldest = geometry::Vec3::Zero();  // mm: where min is
  bool finite = true;     // every temperature a number (a tier's defect otherwise)
  double difference = 0;  // K: the area-weighted mean |T - T across the part's wall| over the
                          // samples paired with the part's other face (eval::across_part)
  double std_side = 0;    // K: the larger of the core side's and the cavity side's spread (eval::part_sides)
};

TemperatureObjectives temperature_objectives(const std::vector<double>& temperature, const thermal::Samples& samples,
                                             const mold::MoldSpec& spec);

}  // namespace mtcs::eval
