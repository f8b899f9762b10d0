#pragma once
// The mold as the page draws it: the block, the part (cavity) and the keep-outs, in mm.

#include <nlohmann/json.hpp>

#include "mtcs/mesh/triangle_mesh.h"
#include "mtcs/mold/mold_spec.h"

namespace mtcs::report {

using Json = nlohmann::ordered_json;

Json vec_json(const geometry::Vec3& v);
// {positions: base64 float32 xyz..., indices: base64 uint32 abc..., triangles: n}
Json mesh_json(const mesh::TriangleMesh& mesh);
// {block, cavity, keep_outs, clearances}: boxes and cylinders as such, meshes as mesh_json.
Json scene_json(const mold::MoldSpec& spec);

}  // namespace mtcs::report
