#include "mtcs/eval/cavity_temperature_report.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <sstream>

#include "circuit_hydraulics_report.h"
#include "mtcs/mesh/surface_field.h"

namespace mtcs::eval {

namespace {

std::string condition_text(const CavityConditionUsed& c) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(1);
  if (c.model != "coupled") {
    s << "fixed flux " << c.heat_flux << " W/m^2";
    return s.str();
  }
  s << "coupled, q = " << c.part_film << " W/(m^2 K) x (" << c.part_temperature << " degC - wall) (cycle " << c.cycle
    << " s, " << c.in_mold << " s in the mold; part wall ";
  if (c.local_wall) s << "local, " << c.wall_thinnest << " to " << c.wall_thickest << " mm, each place with its own film";
  else s << c.wall_thickest << " mm";
  s << ")";
  return s.str();
}

}  // namespace

// The coupled condition's bound (T_p) is the temperature stage's to enforce, with the line sinks'
// slack and without it where regions add a fixed flux; here only the fixed flux, whose heat goes
// in whatever the wall's temperature, is judged against the melt.
bool above_melt(const CavityTemperature& r) {
  return r.condition.model != "coupled" && r.summary.max > r.condition.melt_temperature;
}

std::string above_melt_text(const CavityTemperature& r) {
  if (!above_melt(r)) return "";
  std::ostringstream s;
  s << std::fixed << std::setprecision(1) << "WARNING: physically impossible: the wall reaches " << r.summary.max
    << " degC at (" << r.hottest.x() << ", " << r.hottest.y() << ", " << r.hottest.z() << ") mm, above the "
    << "melt's " << r.condition.melt_temperature << " degC that heats it. The fixed flux puts its heat in whatever the "
    << "wall's temperature; thermal.cavity_condition: coupled lets the part heat the steel only while the steel is colder "
       "(docs/thermal-model.md).";
  return s.str();
}

namespace {

std::string cycle_text(const CavityTemperature& r) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(1);
  if (!r.ejectable) {
    s << "not ejectable: the wall reaches " << r.summary.max << " degC at (" << r.hottest.x() << ", " << r.hottest.y()
      << ", " << r.hottest.z() << ") mm, at or above the eject temperature: the part never sets there\n";
  } else if (r.condition.model == "coupled") {
    s << "cycle " << r.cycle_time << " s: cooling " << r.cooling_time << " s at the ";
    if (r.condition.local_wall)
      s << "place that cools last, (" << r.slowest.x() << ", " << r.slowest.y() << ", " << r.slowest.z() << ") mm, its wall "
        << r.slowest_wall << " mm";
    else
      s << "hottest sample";
    if (r.cycle_iterations > 1) s << " (the film's cycle, consistent after " << r.cycle_iterations << " solves)";
    if (std::abs(r.cycle_time - r.condition.cycle) > 0.05 * r.condition.cycle)
      s << " (the film assumed a " << r.condition.cycle << " s cycle: set thermal.cycle.cooling to " << r.cooling_time
        << " for a consistent one)";
    s << "\n";
  } else {
    s << "cooling time " << r.cooling_time << " s at the hottest sample\n";
  }
  return s.str();
}

std::string across_text(const CavityTemperature& r) {
  if (r.across.pairs == 0) return "";
  std::ostringstream s;
  s << std::fixed << std::setprecision(1) << "core/cavity difference across the wall: mean " << r.across.mean
    << " K, max " << r.across.max << " K at (" << r.across.where.x() << ", " << r.across.where.y() << ", "
    << r.across.where.z() << ") mm (" << r.across.pairs << " samples, " << std::setprecision(0)
    << r.across.paired_area << " mm^2, with the part's other face within 3 walls)\n";
  return s.str();
}

std::string sides_text(const CavityTemperature& r) {
  if (!r.sides) return "";
  std::ostringstream s;
  s << std::fixed << std::setprecision(1) << "per side (cavity.parting), area-weighted:\n";
  for (const auto& [name, side] : {std::pair{"core", r.sides->core}, std::pair{"cavity", r.sides->cavity}}) {
    if (side.area <= 0) {  // e.g. the plate's top: no heat enters it, not among the heated samples
      s << "  " << name << " side: no samples of the " << r.surface << " surface\n";
      continue;
    }
    s << "  " << name << " side: mean " << side.mean << " degC, std " << side.std << " K, max " << side.max
      << " degC over " << std::setprecision(0) << side.area << std::setprecision(1) << " mm^2\n";
  }
  return s.str();
}

nlohmann::json side_json(const SideSummary& s) {
  if (s.area <= 0) return {{"area", 0}, {"mean", nullptr}, {"std", nullptr}, {"max", nullptr}};
  return {{"area", s.area}, {"mean", s.mean}, {"std", s.std}, {"max", s.max}};
}

nlohmann::ordered_json condition_json(const CavityConditionUsed& c) {
  if (c.model == "coupled")
    return {{"model", c.model}, {"part_film", c.part_film}, {"part_temperature", c.part_temperature},
            {"in_mold", c.in_mold}, {"cycle", c.cycle},
            {"wall_thickness", {{"local", c.local_wall}, {"thinnest", c.wall_thinnest}, {"thickest", c.wall_thickest}}}};
  return {{"model", c.model}, {"heat_flux", c.heat_flux}};
}

}  // namespace

void write_cavity_temperature_text(std::ostream& out, const CavityTemperature& r) {
  const std::size_t samples = r.at_samples.size();
  const auto& s = r.summary;
  out << std::fixed << std::setprecision(3) << "cavity temperature (tier " << r.tier << ", " << samples
      << " samples of the " << r.surface << " surface, area-weighted)\n"
      << "  mean " << s.mean << " degC, std " << s.std << " K, max " << s.max << " degC at ("
      << std::setprecision(1) << r.hottest.x() << ", " << r.hottest.y() << ", " << r.hottest.z() << ") mm\n"
      << std::setprecision(1) << "cavity condition: " << condition_text(r.condition) << "\n"
      << (above_melt(r) ? above_melt_text(r) + "\n" : "")
      << cycle_text(r) << across_text(r) << sides_text(r)
      << std::setprecision(3) << "heat balance\n  in " << r.balance.in << " W = bores "
      << r.balance.to_channels << " W + outer faces " << r.balance.to_faces << " W (residual "
      << std::scientific << std::setprecision(1) << r.balance.residual() << " W)\n"
      << std::fixed << coolant_circuits_text(r.circuits) << std::setprecision(3) << "seconds " << r.seconds << "\n";
}

void write_cavity_temperature_field(std::ostream& out, const CavityTemperature& r, bool vtp) {
  if (vtp) return mesh::write_vtp(out, r.field);
  double coldest = r.summary.max;
  for (double t : r.field.values) coldest = std::min(coldest, t);
  mesh::write_ply(out, r.field, std::max(coldest, r.summary.mean - 3 * r.summary.std) - 1e-9, r.summary.max);
}

void write_cavity_temperature_json(std::ostream& out, const CavityTemperature& r, std::ostream& warnings) {
  if (above_melt(r)) warnings << "mtcs thermal: " << above_melt_text(r) << "\n";
  nlohmann::ordered_json j{{"tier", r.tier},
                                 {"cavity_condition", condition_json(r.condition)},
                                 {"mean", r.summary.mean},
                                 {"std", r.summary.std},
                                 {"max", r.summary.max},
                                 {"hottest", {r.hottest.x(), r.hottest.y(), r.hottest.z()}},
                                 {"above_melt", above_melt(r)},
                                 {"surface", r.surface},
                                 {"samples", r.at_samples.size()},
                                 {"heat_in", r.balance.in},
                                 {"heat_to_bores", r.balance.to_channels},
                                 {"heat_to_faces", r.balance.to_faces},
                                 {"cooling_time", r.cooling_time},
                                 {"cycle_time", r.cycle_time},
                                 {"slowest", {r.slowest.x(), r.slowest.y(), r.slowest.z()}},
                                 {"slowest_wall", r.slowest_wall},
                                 {"ejectable", r.ejectable},
                                 {"cycle_iterations", r.cycle_iterations},
                                 {"temperature_difference",
                                  {{"pairs", r.across.pairs}, {"paired_area", r.across.paired_area},
                                   {"mean", r.across.mean}, {"max", r.across.max}}},
                                 {"seconds", r.seconds}};
  if (r.sides) j["sides"] = {{"core", side_json(r.sides->core)}, {"cavity", side_json(r.sides->cavity)}};
  if (r.circuits.flowing) j["coolant"] = coolant_circuits_json(r.circuits);
  out << j.dump(2) << "\n";
}

void write_point_temperatures_csv(std::ostream& out, const std::vector<geometry::Vec3>& points,
                                  const std::vector<double>& temperatures) {
  // The shortest text that reads back to the same double: the user's 83.9 stays 83.9.
  auto cell = [&](double v, char then) {
    char text[32];
    out.write(text, std::to_chars(text, text + sizeof text, v).ptr - text) << then;
  };
  out << "x,y,z,T\n";
  for (std::size_t i = 0; i < points.size(); ++i) {
    cell(points[i].x(), ',');
    cell(points[i].y(), ',');
    cell(points[i].z(), ',');
    cell(temperatures[i], '\n');
  }
}

}  // namespace mtcs::eval
