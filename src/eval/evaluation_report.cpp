#include "mtcs/eval/evaluation_report.h"

#include <iomanip>
#include <nlohmann/json.hpp>
#include <sstream>

#include "circuit_hydraulics_report.h"
#include "mtcs/eval/design_rules.h"
#include "mtcs/eval/drill_access.h"

namespace mtcs::eval {
namespace {

// What a violation found against what its rule needs, with units: clearances and port offsets
// in mm, the depth limit as a depth/diameter ratio, the entry angle in degrees.
std::string found_and_needed(const Violation& v) {
  std::ostringstream s;
  s << std::setprecision(10);
  using K = ViolationKind;
  switch (v.kind) {
    case K::DepthRatio:
      s << "depth/diameter " << v.distance << ", at most " << v.margin;
      break;
    case K::EntryAngle:
      s << "entry angle " << v.distance << " deg, at most " << v.margin << " deg";
      break;
    case K::EntryFace:
      s << "drilled from a face that is not allowed";
      break;
    case K::Drillable:
      s << "direction in a blocked cell, the nearest free one " << v.distance << " deg away";
      break;
    case K::Eject:
      s << "wall at " << v.distance << " degC, the part sets only below " << v.margin << " degC";
      break;
    case K::TemperatureBounds:
      s << "the thermal tier returned " << v.distance << " degC, beyond the physical bound " << v.margin
        << " degC: a defect of the model (please report the layout)";
      break;
    case K::CoolantReynolds:
      s << std::fixed << std::setprecision(0) << "Reynolds number " << v.distance << ", at least " << v.margin
        << " (thermal.coolant.min_reynolds)";
      break;
    case K::CoolantPressure:
      s << std::fixed << std::setprecision(3) << "pressure drop " << v.distance / 1e5 << " bar, the supply gives "
        << v.margin / 1e5 << " bar";
      break;
    case K::CoolantBalance:
      s << std::fixed << std::setprecision(2) << "heat " << v.distance << " times the circuits' mean, the band's edge "
        << v.margin << " (thermal.coolant.balance)";
      break;
    case K::CoolantRise:
      s << std::fixed << std::setprecision(2) << "coolant rise " << v.distance << " K, at most " << v.margin
        << " K (thermal.coolant.max_rise)";
      break;
    case K::InletFace:
    case K::OutletFace:
      s << v.distance << " mm from the nearest allowed face";
      break;
    case K::BoreBore:
    case K::BoreKeepout:
    case K::BoreCavity:
    case K::BoreSurface:
      // A distance of 0 is an overlap, not a thin wall: said in words (a bore through the part).
      if (v.distance <= 0)
        s << (v.kind == K::BoreBore      ? "the bores intersect"
              : v.kind == K::BoreKeepout ? "the bore crosses the keep-out"
              : v.kind == K::BoreCavity  ? "the bore crosses the part"
                                         : "the bore breaks through the block's face")
          << " (found 0 mm, needs " << v.margin << " mm)";
      else
        s << "found " << v.distance << " mm, needs " << v.margin << " mm";
      break;
  }
  return s.str();
}

}  // namespace

std::string violation_text(const Violation& v) {
  std::string s = to_string(v.kind);
  for (const auto& el : v.elements) (s += ' ') += el;
  return s + ": " + found_and_needed(v);
}

void write_evaluation_json(std::ostream& out, const Evaluation& e, const Pipeline& pipeline, const mold::MoldSpec& spec,
                           const mold::Layout& layout, const std::vector<mold::LayoutChange>& changes) {
  nlohmann::ordered_json j;
  j["feasible"] = e.feasible();
  j["objectives"] = nlohmann::ordered_json::object();
  const auto names = pipeline.objective_names();
  for (std::size_t k = 0; k < names.size(); ++k) j["objectives"][names[k]] = e.objectives[k];
  j["scalarised"] = scalar_fitness(e, spec, {});
  j["violation"] = e.violation;
  j["violations"] = nlohmann::ordered_json::array();
  for (const auto& v : e.violations) {
    j["violations"].push_back({{"kind", to_string(v.kind)},
                               {"elements", v.elements},
                               {"distance", v.distance},
                               {"margin", v.margin},
                               {"where", {v.where.x(), v.where.y(), v.where.z()}}});
  }
  if (const DrillAccess* access = pipeline.drill_access()) {
    j["drillable"] = nlohmann::ordered_json::array();
    for (const auto& b : layout.bores) {
      const DrillVerdict v = access->check(b);
      j["drillable"].push_back({{"bore", b.name()}, {"free", v.free}, {"cell", v.cell}, {"map", {v.rows, v.cols}},
                                {"free_cells", v.free_cells}, {"pivot", {v.pivot.x(), v.pivot.y(), v.pivot.z()}},
                                {"tool", {{"radius", v.tool_radius}, {"length", v.tool_length}}},
                                {"draw", access->access_map_command(v)}});
    }
  }
  if (const CoolantCircuits cc = coolant_circuits(layout, spec, e.bore_heat); cc.flowing)
    j["coolant"] = coolant_circuits_json(cc);
  j["design_rules"] = nlohmann::ordered_json::parse(design_rules_json_text(design_rules(pipeline.scene(), layout)));
  j["stages"] = nlohmann::ordered_json::array();
  for (const auto& s : e.stages) j["stages"].push_back({{"name", s.name}, {"seconds", s.seconds}});
  j["changes"] = nlohmann::ordered_json::array();
  for (const auto& c : changes) j["changes"].push_back({{"circuit", c.circuit}, {"waypoint", c.waypoint}, {"what", c.what}});
  out << j.dump(2) << "\n";
}

void write_evaluation_text(std::ostream& out, const Evaluation& e, const Pipeline& pipeline, const mold::MoldSpec& spec,
                           const mold::Layout& layout, const std::vector<mold::LayoutChange>& changes) {
  // What the drilling plan changed in the layout as written comes first: the rest scores it.
  if (!changes.empty()) out << "changed from the layout as written\n";
  for (const auto& c : changes) out << "  " << c.what << "\n";
  if (!changes.empty()) out << "\n";
  double dead = 0;
  for (const auto& b : layout.bores) dead += b.dead_end;
  out << "bores " << layout.bores.size() << ", plugs " << layout.plugs << " (dead ends " << dead
      << " mm), designed junctions " << layout.junctions.size() << ", surface samples "
      << pipeline.surface_samples() << "\n\nobjectives\n";
  const auto names = pipeline.objective_names();
  for (std::size_t k = 0; k < names.size(); ++k)
    out << "  " << std::left << std::setw(16) << names[k] << std::setprecision(10) << e.objectives[k] << "\n";
  out << "  scalarised      " << scalar_fitness(e, spec, {})
      << "  (sum of objective / scale + penalty: what mtcs optimize ranks with weights 1)\n";
  out << "\n"
      << (e.feasible() ? "feasible" : "infeasible") << ": " << e.violations.size()
      << " violated constraint(s), total violation " << e.violation << "\n";
  for (const auto& v : e.violations) {
    out << "  " << std::setw(14) << to_string(v.kind) << " ";
    for (const auto& el : v.elements) out << el << " ";
    out << found_and_needed(v) << " at (" << v.where.x() << ", " << v.where.y() << ", " << v.where.z()
        << ") mm\n";
  }
  if (const DrillAccess* access = pipeline.drill_access()) {
    out << "\ndrillable (accessibility map at each entry, " << access->spec().grid << "^3 voxels)\n";
    for (const auto& b : layout.bores) {
      const DrillVerdict v = access->check(b);
      out << "  " << b.name() << " " << describe(v) << "\n    draw: " << access->access_map_command(v) << "\n";
    }
  }
  // The heat and the rise come from the temperature stage's solve (none without a temperature objective).
  if (const CoolantCircuits cc = coolant_circuits(layout, spec, e.bore_heat); cc.flowing)
    out << "\n" << coolant_circuits_text(cc)
        << (e.bore_heat.empty() ? "  (heat and coolant rise: mtcs thermal)\n" : "");
  out << "\n" << design_rules_text(design_rules(pipeline.scene(), layout));
  out << "\nstages (microseconds)\n";
  for (const auto& s : e.stages) out << "  " << std::setw(24) << s.name << s.seconds * 1e6 << "\n";
}

}  // namespace mtcs::eval
