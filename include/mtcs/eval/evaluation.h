#pragma once
// The score of one layout: objectives, violated constraints with the elements involved, and the
// penalty (shared/notes/mtcs_literature.md 7.4, 7.5).

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "mtcs/mold/mold_spec.h"

namespace mtcs::eval {

// What a violation is about. The printed names (to_string) are the CLI's and the run store's words.
enum class ViolationKind {
  BoreBore,     // two bores closer than clearances.bore_bore
  BoreKeepout,  // a bore too close to a keep-out
  BoreCavity,   // a bore too close to the cavity
  BoreSurface,  // a bore too close to the block's outer surface
  DepthRatio,   // a hole deeper than drilling.max_depth_ratio diameters
  EntryFace,    // drilled from a face not in drilling.allowed_faces
  EntryAngle,   // drill axis too steep against its entry face
  InletFace,    // an inlet away from its allowed faces
  OutletFace,   // an outlet away from its allowed faces
  Drillable,    // a bore's direction in a blocked cell of the accessibility map at its entry
  Eject,        // coupled cavity: the wall stays at or above the eject temperature somewhere, so
                // the part never sets there
  TemperatureBounds,  // coupled cavity: the tier returned a temperature outside [coldest of
                      // coolant and air, T_p] (or not a number): a defect of the model, the
                      // layout refused rather than scored; only on a layout meeting every
                      // geometric rule
  CoolantReynolds,    // a circuit's Reynolds number below thermal.coolant.min_reynolds
  CoolantPressure,    // a circuit's pressure drop above thermal.coolant.supply_pressure
  CoolantRise,        // a circuit's coolant warming by more than thermal.coolant.max_rise
                      // (needs the solve's heat: a thermal verdict)
  CoolantBalance,     // a circuit's heat outside thermal.coolant.balance around the circuits'
                      // mean (a thermal verdict)
};
// The thermal verdicts (eject, temperature_bounds, coolant_rise, coolant_balance), from the
// temperature stage;
// temperature_bounds counts only on a layout that meets every geometric rule (a bore through the
// part has no meaningful temperature).
bool is_thermal_verdict(ViolationKind kind);
// A rule of the layout's geometry (clearances, drilling, ports): neither a thermal verdict nor a
// circuit's coolant limit (coolant_reynolds, coolant_pressure), which no move of a bore can mend.
bool is_geometric(ViolationKind kind);

// bore_bore, bore_keepout, bore_cavity, bore_surface, depth_ratio, entry_face, entry_angle,
// inlet_face, outlet_face, drillable, eject, temperature_bounds, coolant_reynolds,
// coolant_pressure, coolant_rise, coolant_balance.
const char* to_string(ViolationKind kind);

struct Violation {
  ViolationKind kind = ViolationKind::BoreBore;
  std::vector<std::string> elements;  // bore names (c0.b3), keep-out names, "cavity", "block"
  double distance = 0;                // what was found (mm, or the ratio/angle for drilling limits)
  double margin = 0;                  // what is required
  double amount = 0;                  // normalised shortfall, > 0: |distance - margin| / margin
  geometry::Vec3 where = geometry::Vec3::Zero();  // a point near the violation
  // The closest points of the two elements (elements[0]'s first), when a clearance kernel
  // measured them: the report draws the shortfall as the segment between them.
  std::optional<std::pair<geometry::Vec3, geometry::Vec3>> closest;
};

struct StageTime {
  std::string name;
  double seconds = 0;
};

struct Evaluation {
  std::vector<double> objectives;  // raw values, in the order of objectives.use
  std::vector<Violation> violations;
  double violation = 0;            // CV = sum of amount^power
  std::vector<StageTime> stages;   // filled when timing was asked for
  std::vector<double> bore_heat;   // W into each bore's coolant (the layout's order), when a
                                   // temperature stage solved and its tier says

  bool feasible() const { return violations.empty(); }
};

// One number per layout for single-objective search: the scaled, weighted objectives plus the
// penalty variant's term. The score the optimisers rank (feasibility, violation, this value) is
// opt::Score, built by run::MoldProblem; under constrained domination feasible layouts come
// first (opt::feasible_first).
double scalar_fitness(const Evaluation& e, const mold::MoldSpec& spec, const std::vector<double>& weights);
// The penalty variant's term, in scaled-objective units: weight x CV (static linear), weight x
// CV^2 (static quadratic), infinity for an infeasible layout (death), 0 (constrained domination).
double penalty_term(bool feasible, double violation, const mold::Penalty& penalty);

}  // namespace mtcs::eval
