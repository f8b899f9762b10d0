#pragma once
// The page of `mtcs interfere A B --report out.html` (Song et al.'s viewer): one self-contained
// HTML file with both components, the triangles of every intersecting pair highlighted
// (interference red, contact yellow), the intersection segments, and the pairs listed by solid
// and face and one by one. The numbers are those of `mtcs interfere --json`.

#include <string>
#include <vector>

#include "mtcs/mesh/interference.h"
#include "mtcs/mesh/interference_report.h"
#include "mtcs/mesh/interference_view.h"

namespace mtcs::report {

std::string interference_page(const mesh::InterferenceCheck& what, const mesh::TriangleMesh& a, const mesh::TriangleMesh& b,
                              const mesh::InterferenceReport& report, const mesh::MeshParts& pa, const mesh::MeshParts& pb,
                              const std::vector<mesh::FaceGroup>& groups);

}  // namespace mtcs::report
