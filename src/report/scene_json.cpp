#include "scene_json.h"

#include "base64.h"

namespace mtcs::report {
namespace {

Json box_json(const geometry::Box& b) { return {{"min", vec_json(b.min)}, {"max", vec_json(b.max)}}; }

}  // namespace

Json vec_json(const geometry::Vec3& v) { return Json::array({v.x(), v.y(), v.z()}); }

Json mesh_json(const mesh::TriangleMesh& mesh) {
  std::vector<float> positions;
  positions.reserve(mesh.vertices.size() * 3);
  for (const auto& v : mesh.vertices)
    for (int k = 0; k < 3; ++k) positions.push_back(float(v[k]));
  std::vector<std::uint32_t> indices;
  indices.reserve(mesh.triangles.size() * 3);
  for (const auto& t : mesh.triangles)
    for (const int i : t) indices.push_back(std::uint32_t(i));
  return {{"positions", base64_floats(positions)}, {"indices", base64_indices(indices)}, {"triangles", mesh.triangles.size()}};
}

Json scene_json(const mold::MoldSpec& spec) {
  Json scene;
  scene["block"] = spec.block.mesh ? Json{{"mesh", mesh_json(spec.block.mesh->mesh)}} : Json{{"box", box_json(*spec.block.box)}};
  if (!spec.cavity) {
    scene["cavity"] = nullptr;
  } else if (spec.cavity->mesh) {
    scene["cavity"] = {{"mesh", mesh_json(spec.cavity->mesh->mesh)}};
  } else {
    scene["cavity"] = {{"box", box_json(*spec.cavity->box)}};
    if (spec.cavity->patch_face) scene["cavity"]["patch_face"] = mold::to_string(*spec.cavity->patch_face);
  }
  scene["keep_outs"] = Json::array();
  for (const auto& k : spec.keep_outs) {
    Json j{{"name", k.name}, {"clearance", k.clearance}};
    if (k.cylinder)
      j["cylinder"] = {{"p0", vec_json(k.cylinder->p0)}, {"p1", vec_json(k.cylinder->p1)}, {"radius", k.cylinder->radius}};
    else
      j["mesh"] = mesh_json(k.mesh->mesh);
    scene["keep_outs"].push_back(std::move(j));
  }
  const auto& c = spec.clearances;
  scene["clearances"] = {{"bore_bore", c.bore_bore},
                         {"bore_cavity", {{"value", c.bore_cavity.value}, {"per_diameter", c.bore_cavity.per_diameter}}},
                         {"bore_surface", c.bore_surface}};
  return scene;
}

}  // namespace mtcs::report
