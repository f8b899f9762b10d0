#pragma once
// The thermal tiers as the pipeline's temperature solvers: the spec's `thermal.tier` picks one
// (t1, t2, t2d: line sinks with `elements_per_bore`; fd: finite volumes at `cell_size`).

#include "mtcs/eval/temperature_objectives.h"
#include "mtcs/mold/mold_spec.h"

namespace mtcs::thermal {
enum class Tier;  // mtcs/thermal/line_sinks.h
}  // namespace mtcs::thermal

namespace mtcs::eval {

// The factory for that tier. Line sinks keep one cache per thread, so that a layout sharing
// channels with the one the same thread scored last recomputes only the channels that changed
// (the result is bit-identical to a cold evaluation: the thread count does not change it).
TemperatureSolverFactory temperature_solver(mold::ThermalTier tier);

// The line-sink tier a spec's tier names (fd, which is not one, maps to t2d).
thermal::Tier line_sink_tier(mold::ThermalTier tier);

}  // namespace mtcs::eval
