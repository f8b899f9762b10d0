#pragma once
// Two meshes' interference as `mtcs interfere A B` prints it: the verdict, the pairs, the nesting,
// the groups by solid and face, as text or one JSON object (keys sorted; segments as point pairs).

#include <ostream>
#include <string>
#include <vector>

#include "mtcs/mesh/interference.h"
#include "mtcs/mesh/interference_view.h"
#include "mtcs/mesh/mesh_parts.h"

namespace mtcs::mesh {

// What was checked: the two meshes' names, B's translation, the touch tolerance used.
struct InterferenceCheck {
  std::string a, b;
  std::vector<double> translate;
  double tolerance = 0;
};

// Each group also says where its two faces are (centroid and area, B as placed).
void write_interference_json(std::ostream& out, const InterferenceCheck& what, const TriangleMesh& a,
                             const TriangleMesh& b, const InterferenceReport& report, const MeshParts& pa,
                             const MeshParts& pb, const std::vector<FaceGroup>& groups);
void write_interference_text(std::ostream& out, const InterferenceCheck& what, const TriangleMesh& a, const TriangleMesh& b,
                             const InterferenceReport& report, const MeshParts& pa, const MeshParts& pb,
                             const std::vector<FaceGroup>& groups);

}  // namespace mtcs::mesh
