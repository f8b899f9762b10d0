// A user's part on a grid fitted to it, and the tools users name.

#include "mtcs/voxel/part_map.h"

#include <cmath>
#include <iomanip>
#include <stdexcept>

#include "mtcs/io/input_error.h"
#include "mtcs/io/yaml_reader.h"
#include "mtcs/mesh/mesh_io.h"
#include "mtcs/voxel/octree.h"

namespace mtcs::voxel {

GridSpec part_grid(const mesh::TriangleMesh& part, int n) {
  if (n < 3 || n > 4096) throw std::invalid_argument("grid must be 3 to 4096 voxels per side, got " + std::to_string(n));
  if (part.vertices.empty()) throw std::invalid_argument("the mesh has no vertices");
  const Box b = part.bounds();
  const double extent = b.size().maxCoeff();
  if (!(extent > 0) || !std::isfinite(extent)) throw std::invalid_argument("the mesh has no extent");
  GridSpec g;
  g.size = {n, n, n};
  g.voxel_size = extent / (n - 2);
  // Centre the bounding box: the grid spans n * voxel_size = extent + 2 voxels on every axis.
  g.origin = 0.5 * (b.min + b.max) - Vec3::Constant(0.5 * n * g.voxel_size);
  return g;
}

Tool bore_tool(double radius, double length) { return {{0, length, radius}}; }

std::string tool_problem(const Tool& tool) {
  if (tool.empty()) return "the tool has no cylinder";
  for (std::size_t i = 0; i < tool.size(); ++i) {
    const ToolCylinder& c = tool[i];
    const std::string at = "cylinder " + std::to_string(i + 1) + ": ";
    if (!std::isfinite(c.a) || !std::isfinite(c.b) || !std::isfinite(c.r)) return at + "non-finite a, b or r";
    if (c.a < 0) return at + "a must be >= 0 (the tool starts at the pivot)";
    if (c.b < c.a) return at + "b must be >= a";
    if (c.r < 0) return at + "r must be >= 0";
  }
  return "";
}

bool pivot_inside(const mesh::TriangleMesh& part, const Octree& tree, const GridSpec& grid, const Vec3& pivot) {
  // The mesh itself: a single-voxel grid centred on the pivot (up to one rounding of its centre).
  GridSpec at_pivot;
  at_pivot.size = {1, 1, 1};
  at_pivot.voxel_size = grid.voxel_size;
  at_pivot.origin = pivot - Vec3::Constant(0.5 * at_pivot.voxel_size);
  return tree.touches_solid(pivot) || voxelize(part, at_pivot).count() > 0;
}

PartMap part_access_map(const mesh::TriangleMesh& part, int n, const Vec3& pivot, const Tool& tool, const SphereGrid& sphere,
                        const AmOptions& options) {
  PartMap out;
  out.grid = part_grid(part, n);
  const Octree tree(voxelize(part, out.grid));
  out.solid_voxels = tree.solid_voxels();
  out.pivot_inside = pivot_inside(part, tree, out.grid, pivot);
  if (!out.pivot_inside) out.map = compute_access_map(tree, pivot, tool, sphere, options);
  return out;
}

Tool read_tool_file(const std::string& path) {
  const io::YamlReader reader(path);
  const YAML::Node root = reader.load();
  reader.expect_sequence(root, "tool");
  Tool tool;
  for (std::size_t i = 0; i < root.size(); ++i) {
    const std::string at = io::indexed("tool", i);
    reader.expect_map(root[i], at, {"a", "b", "r"});
    ToolCylinder c;
    c.a = reader.number(root[i]["a"], at + ".a", 0, 1e9);
    c.b = reader.number(root[i]["b"], at + ".b", c.a, 1e9);
    c.r = reader.number(root[i]["r"], at + ".r", 0, 1e9);
    tool.push_back(c);
  }
  if (tool.empty()) reader.fail(root, "tool", "no cylinder");
  return tool;
}

mesh::TriangleMesh read_part(const std::string& path) {
  mesh::TriangleMesh part;
  try {
    part = mesh::read_mesh(path);
  } catch (const mesh::MeshError& e) {
    throw io::InputError(path, 0, 0, "mesh", e.what());
  }
  if (const std::string problem = mesh::closed_mesh_problem(part); !problem.empty())
    throw io::InputError(path, 0, 0, "mesh", "not a closed mesh: " + problem);
  return part;
}

void write_map_csv(std::ostream& out, const AccessMap& map, const SphereGrid& sphere) {
  out << "phi,gamma,dx,dy,dz,free\n" << std::setprecision(17);
  for (int i = 0; i < sphere.rows; ++i)
    for (int j = 0; j < sphere.cols; ++j) {
      const Vec3 d = sphere.direction(i, j);
      out << (i + 0.5) * 180.0 / sphere.rows << ',' << (j + 0.5) * 360.0 / sphere.cols << ',' << d.x() << ',' << d.y() << ','
          << d.z() << ',' << (map.collides(i, j) ? 0 : 1) << '\n';
    }
}

}  // namespace mtcs::voxel
