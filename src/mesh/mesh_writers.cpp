// Text writers: OBJ and PLY, for viewers (MeshLab, ParaView) and for other tools.

#include <iomanip>
#include <limits>

#include "mtcs/mesh/mesh_io.h"

namespace mtcs::mesh {

void write_obj(std::ostream& out, const TriangleMesh& mesh) {
  out << std::setprecision(std::numeric_limits<double>::max_digits10);
  out << "# written by mtcs\n";
  for (const Vec3& v : mesh.vertices) out << "v " << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
  for (const auto& t : mesh.triangles) out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
}

void write_ply(std::ostream& out, const TriangleMesh& mesh, const FaceAttributes& faces) {
  const bool colors = !faces.colors.empty(), quality = !faces.quality.empty();
  if ((colors && faces.colors.size() != mesh.triangles.size()) || (quality && faces.quality.size() != mesh.triangles.size()))
    throw MeshError("write_ply: per-face attributes must have one entry per triangle");
  out << std::setprecision(std::numeric_limits<double>::max_digits10);
  out << "ply\nformat ascii 1.0\ncomment written by mtcs\n"
      << "element vertex " << mesh.vertices.size() << "\nproperty double x\nproperty double y\nproperty double z\n"
      << "element face " << mesh.triangles.size() << "\nproperty list uchar int vertex_indices\n";
  if (colors) out << "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  if (quality) out << "property float quality\n";
  out << "end_header\n";
  for (const Vec3& v : mesh.vertices) out << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& f = mesh.triangles[t];
    out << "3 " << f[0] << ' ' << f[1] << ' ' << f[2];
    if (colors) out << ' ' << int(faces.colors[t][0]) << ' ' << int(faces.colors[t][1]) << ' ' << int(faces.colors[t][2]);
    if (quality) out << ' ' << float(faces.quality[t]);
    out << '\n';
  }
}

}  // namespace mtcs::mesh
