#include "mtcs/serve/upload_check.h"

#include <stdexcept>

#include "mtcs/mesh/mesh_check.h"
#include "mtcs/mesh/mesh_io.h"

namespace mtcs::serve {

nlohmann::json check_component(const std::filesystem::path& staged) {
  const mesh::TriangleMesh m = mesh::read_mesh(staged.string());
  if (const auto check = mesh::check_mesh(m); !check.ok())
    throw std::runtime_error("not the closed, oriented, self-intersection-free surface of a solid: " + check.message());
  const auto box = m.bounds();
  return {{"triangles", m.triangles.size()},
          {"vertices", m.vertices.size()},
          {"bounds", {{box.min.x(), box.min.y(), box.min.z()}, {box.max.x(), box.max.y(), box.max.z()}}}};
}

}  // namespace mtcs::serve
