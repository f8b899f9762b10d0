// The temperature objectives (docs/mold-spec.md): a thermal tier computes the cycle-averaged
// temperature at the cavity samples for the layout's channels; the objectives are its
// area-weighted mean, standard deviation and maximum, and the plate cooling time at the
// hottest sample.

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "mtcs/eval/across_part.h"
#include "mtcs/eval/circuit_hydraulics.h"
#include "mtcs/eval/cycle_time.h"
#include "mtcs/eval/part_coupling.h"
#include "mtcs/eval/part_sides.h"
#include "mtcs/eval/temperature_objectives.h"
#include "mtcs/eval/thermal_model.h"
#include "exact_cache.h"
#include "stages.h"

namespace mtcs::eval {

TemperatureObjectives temperature_objectives(const std::vector<double>& temperature, const thermal::Samples& samples,
                                             const mold::MoldSpec& spec) {
  const thermal::Summary s = thermal::summarize(temperature, samples);
  double cycle = cooling_time(spec.cavity ? spec.cavity->wall_thickness : mold::Cavity{}.wall_thickness,
                              spec.thermal.polymer, s.max);
  if (!samples.thickness.empty() && !temperature.empty()) {  // the part's local wall: the slowest place decides
    const std::size_t k = slowest_place(temperature, samples.thickness, spec.thermal.polymer, temperature.size());
    cycle = cooling_time(samples.thickness[k], spec.thermal.polymer, temperature[k]);
  }
  // Coupled: the whole cycle, the slowest place (the hottest wall) deciding when to eject.
  if (spec.thermal.cavity_condition == mold::CavityCondition::Coupled)
    cycle += spec.thermal.cycle.fill + spec.thermal.cycle.pack + spec.thermal.cycle.open;
  TemperatureObjectives o{s.mean, s.std, s.max, std::numeric_limits<double>::infinity(), cycle};
  for (std::size_t i = 0; i < temperature.size(); ++i) {
    if (!std::isfinite(temperature[i])) o.finite = false;
    else if (temperature[i] < o.min) o.min = temperature[i], o.coldest = samples.points[i];
  }
  if (!samples.points.empty()) o.hottest = samples.points[s.hottest];
  return o;
}

namespace {

class TemperatureStage final : public Stage {
 public:
  TemperatureStage(const mold::Scene& scene, const TemperatureSolverFactory& factory, thermal::Samples samples)
      : spec_(scene.spec()),
        setting_(thermal_setting(scene)),
        samples_(std::move(samples)),
        coupled_(spec_.thermal.cavity_condition == mold::CavityCondition::Coupled),
        part_temperature_(coupled_ ? cavity_coupling(spec_).temperature : 0),
        bounded_above_(std::none_of(spec_.thermal.regions.begin(), spec_.thermal.regions.end(),
                                    [](const mold::HeatRegion& r) { return r.flux > 0; })),
        samples_count_(samples_.size()),
        flowing_(spec_.thermal.flowing()) {
    const auto& use = spec_.objectives.use;
    // temperature_std_side: each sample's half of the mold (before the points across join).
    if (std::find(use.begin(), use.end(), mold::Objective::TemperatureStdSide) != use.end()) {
      sides_ = part_sides(scene, samples_);
      const SideSummaries area = side_summaries(std::vector<double>(samples_.size(), 0.0), samples_, sides_);
      for (const auto& [name, side] : {std::pair{"core", area.core}, std::pair{"cavity", area.cavity}})
        if (side.area <= 0)  // the larger spread would be the other side's: temperature_std under another name
          throw std::invalid_argument(std::string("temperature_std_side: the ") + name + " side has no samples of the " +
                                      mold::to_string(spec_.thermal.objective_surface) +
                                      " surface (cavity.parting, thermal.objective_surface: all takes every face)");
    }
    // temperature_difference: the part's other face across from each sample joins the points
    // solved for, with no weight (after the samples: their summary is unchanged).
    if (std::find(use.begin(), use.end(), mold::Objective::TemperatureDifference) != use.end()) {
      const double reach = 3 * spec_.cavity->wall_thickness;
      across_ = across_part(scene, samples_, reach);
      if (std::none_of(across_.begin(), across_.end(), [](const auto& q) { return q.has_value(); }))
        throw std::invalid_argument(
            "temperature_difference needs a part whose faces pair across its wall within 3 wall thicknesses "
            "(a box or mesh cavity with cavity.wall_thickness near its real walls); none do here");
      append_across(samples_, across_);
    }
    solve_ = factory(setting_, samples_, spec_.thermal);
    for (std::size_t k = 0; k < use.size(); ++k)
      if (mold::is_temperature_objective(use[k])) slots_.push_back({use[k], k});
  }

  std::string name() const override { return "temperature_" + mold::to_string(spec_.thermal.tier); }

  void run(const mold::Layout& layout, Evaluation& out) const override {
    const std::vector<double> flows = flowing_ ? bore_flows(layout, spec_) : std::vector<double>{};
    const std::vector<thermal::Channel> channels = thermal_channels(layout, spec_, flows);
    // A genome can decode to no bore at all (a circuit whose waypoints collapse). Nothing then
    // carries the heat away in the models: worse than any layout that cools, not an error.
    constexpr double kNoCooling = std::numeric_limits<double>::infinity();
    if (channels.empty()) {
      TemperatureObjectives none{kNoCooling, kNoCooling, kNoCooling, kNoCooling, kNoCooling};
      none.difference = none.std_side = kNoCooling;
      // Coupled, the whole mold goes to the part's temperature: the part never sets.
      if (coupled_)
        out.violations.push_back({ViolationKind::Eject, {"cavity"}, part_temperature_,
                                  spec_.thermal.polymer.eject_temperature, eject_amount(part_temperature_),
                                  samples_.points.empty() ? geometry::Vec3::Zero() : samples_.points[0], {}});
      return write(none, layout, out, false);
    }
    // Every number the solve reads of the channels: a child that decodes to a layout solved
    // before gets that solve's objectives (on the plate 1 in 5 of the layouts an ES run solves
    // repeats an earlier one: a move undone by the decoder's snapping, a parent crossed with itself).
    thread_local std::vector<double> key;
    key.clear();
    for (const thermal::Channel& c : channels)
      key.insert(key.end(), {c.axis.p0.x(), c.axis.p0.y(), c.axis.p0.z(), c.axis.p1.x(), c.axis.p1.y(), c.axis.p1.z(),
                             c.radius, c.coolant, c.film, double(c.circuit), c.position, c.capacity});
    const Solved& solved = solved_.get(key, [&] {
      SolvedTemperatures t = solve_(channels);
      const std::vector<double> before(t.temperature.begin(),
                                       t.temperature.begin() + std::ptrdiff_t(std::min(samples_count_, t.temperature.size())));
      follow_cycle(t.temperature, spec_, samples_count_, samples_.thickness);  // coupled: the film of the cycle this layout needs
      const double scale = heat_scale(before, t.temperature);
      for (double& q : t.channel_heat) q *= scale;
      return Solved{objectives_of(std::move(t.temperature)), std::move(t.channel_heat)};
    });
    write(solved.objectives, layout, out);
    // Each bore's heat (a channel per bore); the coolant's rise and the circuits' balance against the shop's limits.
    if (solved.bore_heat.size() != layout.bores.size()) return;
    out.bore_heat = solved.bore_heat;
    if (!flows.empty()) add_shop_checks(out, heat_checks(layout, spec_, flows, out.bore_heat), layout);
  }

 private:
  struct Solved {
    TemperatureObjectives objectives;
    std::vector<double> bore_heat;  // W per bore, at the film of the cycle the layout needs
  };

  // follow_cycle moves each sample's wall for the film of the cycle this layout needs; the heat
  // through a sample then scales as its excess over the coolant does (q = h (T_p - T) with
  // T - T_c proportional to q, the 1-D picture follow_cycle itself rests on), so the bores' heat
  // scales by the samples' heat-weighted mean of that ratio (1 under the flux model).
  double heat_scale(const std::vector<double>& before, const std::vector<double>& after) const {
    if (!coupled_ || before.size() > after.size()) return 1;
    const double coolant = spec_.thermal.coolant_temperature;
    double q = 0, q_after = 0;
    for (std::size_t i = 0; i < before.size() && i < samples_.weights.size(); ++i) {
      const double excess = before[i] - coolant, took = samples_.weights[i] * (part_temperature_ - before[i]);
      if (!(excess > 0) || !(took > 0)) continue;
      q += took, q_after += took * (after[i] - coolant) / excess;
    }
    return q > 0 ? q_after / q : 1;
  }

  // The objectives of the samples' temperatures (the points across the part after them).
  TemperatureObjectives objectives_of(std::vector<double> t) const {
    std::vector<double> across(t.begin() + std::ptrdiff_t(samples_count_), t.end());
    t.resize(samples_count_);
    TemperatureObjectives o = temperature_objectives(t, samples_, spec_);
    if (!across_.empty()) o.difference = wall_difference(t, across, samples_, across_).mean;
    if (!sides_.empty()) o.std_side = side_summaries(t, samples_, sides_).larger_std();
    return o;
  }

  double eject_amount(double wall) const {
    const mold::ThermalSpec& t = spec_.thermal;
    return (wall - t.polymer.eject_temperature) / std::max(t.polymer.eject_temperature - t.coolant_temperature, 1.0);
  }

  // Under the coupled condition every boundary links to the part (T_p), the coolant or the
  // ambient air (a fixed flux in a region may add heat: then no upper bound): a temperature
  // outside that range, or not a number, is a defect of the tier, and the layout is refused with
  // it rather than scored (Pipeline::evaluate counts it on a buildable layout only). A wall at or
  // above the eject temperature is a design the part cannot leave.
  void check_coupled(const TemperatureObjectives& o, Evaluation& out) const {
    const mold::ThermalSpec& t = spec_.thermal;
    const double coldest = std::min(t.coolant_temperature, t.ambient_temperature);
    const double span = std::max(part_temperature_ - coldest, 1.0);
    if (!o.finite)
      out.violations.push_back({ViolationKind::TemperatureBounds, {"cavity"}, std::nan(""), part_temperature_, 2,
                                o.hottest, {}});
    else if (bounded_above_ && o.max > part_temperature_ + kBoundSlack)
      out.violations.push_back({ViolationKind::TemperatureBounds, {"cavity"}, o.max, part_temperature_,
                                1 + (o.max - part_temperature_) / span, o.hottest, {}});
    else if (o.min < coldest - kBoundSlack)
      out.violations.push_back({ViolationKind::TemperatureBounds, {"cavity"}, o.min, coldest,
                                1 + (coldest - o.min) / span, o.coldest, {}});
    if (o.max >= t.polymer.eject_temperature)
      out.violations.push_back({ViolationKind::Eject, {"cavity"}, o.max, t.polymer.eject_temperature,
                                eject_amount(o.max), o.hottest, {}});
  }

  void write(const TemperatureObjectives& o, const mold::Layout& layout, Evaluation& out, bool solved = true) const {
    if (coupled_ && solved) check_coupled(o, out);
    for (const auto& [objective, slot] : slots_) {
      double& v = out.objectives[slot];
      switch (objective) {
        case mold::Objective::TemperatureMean: v = o.mean; break;
        case mold::Objective::TemperatureStd: v = o.std; break;
        case mold::Objective::TemperatureMax: v = o.max; break;
        case mold::Objective::CycleTime: v = o.cycle_time; break;
        case mold::Objective::TemperatureDifference: v = o.difference; break;
        case mold::Objective::TemperatureStdSide: v = o.std_side; break;
        case mold::Objective::CostPerPart: {
          const mold::Objectives& s = spec_.objectives;
          v = drilling_cost(layout, s) / s.production->parts + s.production->machine_rate * o.cycle_time / 3600;
          break;
        }
        default: break;
      }
    }
  }

  static constexpr double kBoundSlack = 0.5;  // K: the line sinks' discretisation, well above
                                              // what the tests find (tests/eval/coupled_molds_test.cpp)
  const mold::MoldSpec& spec_;
  thermal::Setting setting_;
  thermal::Samples samples_;
  bool coupled_;
  double part_temperature_;
  bool bounded_above_;  // no region adds a fixed flux: nothing can heat the steel above T_p
  std::size_t samples_count_;                              // the samples (the points across after them)
  std::vector<std::optional<geometry::Vec3>> across_;       // per sample, the point across the part
  std::vector<PartSide> sides_;                             // per sample, its half (temperature_std_side)
  TemperatureSolver solve_;
  bool flowing_;  // a flow rate, a supply pressure or a pump: each bore's flow known, the rise checked
  ExactCache<std::vector<double>, Solved> solved_{256};
  std::vector<std::pair<mold::Objective, std::size_t>> slots_;
};

}  // namespace

std::unique_ptr<Stage> make_temperature_stage(const mold::Scene& scene, const TemperatureSolverFactory& factory,
                                              thermal::Samples samples) {
  return std::make_unique<TemperatureStage>(scene, factory, std::move(samples));
}

}  // namespace mtcs::eval
