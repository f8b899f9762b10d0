// The page's data (what interference.js reads):
//   title, check (exactly `mtcs interfere --json`'s object: pairs with triangles, solids, faces,
//   segments; groups by solid and face; verdict and distance),
//   a, b {mesh (scene_json.h), triangles, solids, faces, hit (triangles in some pair)}

#include "mtcs/report/interference_page.h"

#include <set>
#include <sstream>

#include "mtcs/report/html_page.h"
#include "scene_json.h"

namespace mtcs::report {
namespace {

Json component(const mesh::TriangleMesh& m, const mesh::MeshParts& parts, const std::set<int>& hit) {
  return {{"mesh", mesh_json(m)}, {"triangles", m.triangles.size()}, {"solids", parts.solids},
          {"faces", parts.faces()}, {"hit", hit.size()}};
}

}  // namespace

std::string interference_page(const mesh::InterferenceCheck& what, const mesh::TriangleMesh& a, const mesh::TriangleMesh& b,
                              const mesh::InterferenceReport& report, const mesh::MeshParts& pa, const mesh::MeshParts& pb,
                              const std::vector<mesh::FaceGroup>& groups) {
  std::ostringstream check;  // the command's own JSON: the page and --json cannot disagree
  mesh::write_interference_json(check, what, a, b, report, pa, pb, groups);
  std::set<int> hit_a, hit_b;
  for (const auto& p : report.pairs) hit_a.insert(p.a), hit_b.insert(p.b);
  Json data;
  data["title"] = "mtcs interfere: " + what.a + " vs " + what.b;
  data["check"] = Json::parse(check.str());
  data["a"] = component(a, pa, hit_a);
  data["b"] = component(b, pb, hit_b);
  return html_page(data["title"].get<std::string>(), data.dump(), "interference");
}

}  // namespace mtcs::report
