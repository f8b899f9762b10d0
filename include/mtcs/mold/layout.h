#pragma once
// The phenotype: the drilling plan decoded from a genome. Every flow segment between two
// waypoints is drilled as one straight hole from a block face; a hole not entered at the
// circuit's inlet or outlet is plugged at its entry, and its stretch between the plug and the
// first waypoint is a dead end.

#include <string>
#include <vector>

#include "mtcs/geometry/primitives.h"
#include "mtcs/mold/mold_spec.h"

namespace mtcs::mold {

struct Bore {
  geometry::Cylinder hole;   // entry point -> far end, including the drill point overshoot
  geometry::Vec3 flow_start, flow_end;  // the part the coolant flows through
  Face entry_face = Face::PosX;
  double entry_angle_deg = 0;  // drill axis against the entry face's normal
  bool entry_allowed = true;   // entry face in drilling.allowed_faces
  bool plugged = false;        // entered away from the inlet/outlet: a plug closes the entry
  bool through = false;        // its far end is the circuit's inlet or outlet on its face: drilled through, open there
  double dead_end = 0;         // length of the stagnant stub between the plug and the flow, mm
  double drilled_length = 0;
  double diameter = 0;
  int circuit = 0;
  int segment = 0;             // index of the flow segment in its circuit
  CircuitKind kind = CircuitKind::Drilled;  // blind: a baffle's or bubbler's bore, flow entry -> tip and back
  double tube_outer = 0, tube_inner = 0;    // mm, a bubbler's tube (drilling.baffles.tube)

  std::string name() const { return "c" + std::to_string(circuit) + ".b" + std::to_string(segment); }
};

// Two bores that meet by design (consecutive segments of a circuit): not a collision.
struct Junction {
  int a, b;
};

// An inlet or outlet that is not on one of its allowed faces.
struct PortProblem {
  int circuit;
  bool inlet;
  double off_face;  // distance from the nearest allowed face, mm
};

struct Layout {
  std::vector<Bore> bores;
  std::vector<Junction> junctions;
  std::vector<PortProblem> ports;
  int plugs = 0;
};

}  // namespace mtcs::mold
