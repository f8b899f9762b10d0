#pragma once
// The genotype of a cooling layout (shared/notes/mtcs_literature.md 7.1): circuits, each a chain
// of waypoints from an inlet on a block face to an outlet on a block face, with one diameter; or
// a blind bore into a core with a baffle blade or a bubbler tube in it (docs/coolant-circuits.md).

#include <optional>
#include <string>
#include <vector>

#include "mtcs/geometry/primitives.h"

namespace mtcs::mold {

// Drilled: a chain of holes from inlet to outlet. Baffle and Bubbler: one blind hole drilled
// along a face's normal (waypoints: the entry on the face, then the tip), the coolant led to the
// tip and back by a blade that halves the bore, or up a tube and back down the annulus around it;
// both ports at the entry.
enum class CircuitKind { Drilled, Baffle, Bubbler };
std::string to_string(CircuitKind k);
std::optional<CircuitKind> circuit_kind(const std::string& name);  // as to_string spells it, or none
inline bool is_blind(CircuitKind k) { return k != CircuitKind::Drilled; }

struct Circuit {
  std::vector<geometry::Vec3> waypoints;  // inlet first, outlet last; blind: entry, tip
  double diameter = 8;
  CircuitKind kind = CircuitKind::Drilled;
};

struct Genome {
  std::vector<Circuit> circuits;
};

// How many of g's circuits are baffles or bubblers.
inline int count_blind(const Genome& g) {
  int n = 0;
  for (const Circuit& c : g.circuits) n += is_blind(c.kind) ? 1 : 0;
  return n;
}

}  // namespace mtcs::mold
