// Drilling directions free at a bore's entry, from the accessibility map of the bore as a tool.

#include "mtcs/eval/drill_access.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "mtcs/voxel/part_map.h"

namespace mtcs::eval {

using geometry::Vec3;

namespace {

const mold::MeshSource& cavity_mesh(const mold::Scene& scene) {
  const auto& cavity = scene.spec().cavity;
  if (!cavity || !cavity->mesh || !scene.spec().drilling.access_map)
    throw std::invalid_argument("drilling access maps need drilling.access_map and a cavity mesh");
  return *cavity->mesh;
}

}  // namespace

DrillAccess::DrillAccess(const mold::Scene& scene)
    : scene_(scene),
      spec_(*scene.spec().drilling.access_map),
      cache_(cavity_mesh(scene).mesh, voxel::part_grid(cavity_mesh(scene).mesh, spec_.grid), {spec_.rows, spec_.cols}) {}

Vec3 DrillAccess::rounded(const Vec3& entry) const {
  const double q = spec_.entry_step;
  return {std::round(entry.x() / q) * q, std::round(entry.y() / q) * q, std::round(entry.z() / q) * q};
}

double DrillAccess::tool_radius(double diameter) const {
  return diameter / 2 + scene_.spec().clearances.bore_cavity.at(diameter);
}

double DrillAccess::tool_length(double length) const {
  // Up, so a free verdict holds for the bore itself: a longer tool sweeps a superset.
  return std::ceil(length / spec_.entry_step - 1e-9) * spec_.entry_step;
}

std::shared_ptr<const voxel::AccessMap> DrillAccess::map(const Vec3& pivot, double radius, double length) const {
  return cache_.at(pivot, voxel::bore_tool(radius, length));
}

DrillVerdict DrillAccess::check(const mold::Bore& bore) const {
  return check(bore.hole.p0, bore.hole.p1 - bore.hole.p0, bore.diameter, bore.drilled_length);
}

DrillVerdict DrillAccess::check(const Vec3& entry, const Vec3& direction, double diameter, double length) const {
  DrillVerdict v;
  v.rows = spec_.rows;
  v.cols = spec_.cols;
  v.pivot = rounded(entry);
  v.pivot_in_mesh = v.pivot - cavity_mesh(scene_).translate;
  v.tool_radius = tool_radius(diameter);
  v.tool_length = tool_length(length);
  v.direction = direction.normalized();
  const auto cells = voxel::cells_of(cache_.sphere(), v.direction);
  v.cell = cells.front();
  v.map = map(v.pivot, v.tool_radius, v.tool_length);
  v.pivot_inside = !v.map;
  if (!v.map) return v;
  for (const auto& c : cells)
    if (!v.map->collides(c[0], c[1])) {
      v.free = true;
      v.cell = c;
      break;
    }
  double best = -2;  // cosine of the nearest free centre
  for (int i = 0; i < v.rows; ++i)
    for (int j = 0; j < v.cols; ++j) {
      if (v.map->collides(i, j)) continue;
      ++v.free_cells;
      best = std::max(best, cache_.sphere().direction(i, j).dot(v.direction));
    }
  if (v.free_cells > 0) v.angle_to_free_deg = std::acos(std::clamp(best, -1.0, 1.0)) * 180 / M_PI;
  return v;
}

std::vector<FreeDirection> DrillAccess::free_directions(const Vec3& entry, mold::Face face, double diameter,
                                                        double length) const {
  std::vector<FreeDirection> out;
  const auto m = map(rounded(entry), tool_radius(diameter), tool_length(length));
  if (!m) return out;
  const Vec3 inward = -mold::normal_of(face);
  const double min_cos = std::cos(scene_.spec().drilling.max_angle_deg * M_PI / 180) - 1e-12;
  for (int i = 0; i < spec_.rows; ++i)
    for (int j = 0; j < spec_.cols; ++j) {
      if (m->collides(i, j)) continue;
      const Vec3 d = cache_.sphere().direction(i, j);
      if (d.dot(inward) >= min_cos) out.push_back({{i, j}, d});
    }
  return out;
}

std::string DrillAccess::access_map_command(const DrillVerdict& v) const {
  std::ostringstream s;
  s.precision(17);
  s << "mtcs access-map " << cavity_mesh(scene_).path << " --pivot " << v.pivot_in_mesh.x() << ',' << v.pivot_in_mesh.y()
    << ',' << v.pivot_in_mesh.z() << " --bore " << v.tool_radius << ',' << v.tool_length << " --grid " << spec_.grid
    << " --am " << v.rows << ',' << v.cols << " --out am.png";
  return s.str();
}

std::string describe(const DrillVerdict& v) {
  std::ostringstream s;
  s.precision(10);
  s << (v.free ? "free" : v.pivot_inside ? "blocked (entry inside the part)" : "blocked") << ", cell (" << v.cell[0] << ", "
    << v.cell[1] << ") of " << v.rows << " x " << v.cols << " (" << v.free_cells << " free";
  if (!v.free && v.free_cells > 0) s << ", nearest " << v.angle_to_free_deg << " deg away";
  s << "), pivot (" << v.pivot.x() << ", " << v.pivot.y() << ", " << v.pivot.z() << "), tool r " << v.tool_radius
    << " mm x " << v.tool_length << " mm";
  return s.str();
}

}  // namespace mtcs::eval
