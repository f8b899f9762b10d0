// The drilling maps of a layout's bore entries: one voxelisation, one map per bore.

#include "mtcs/report/drilling_maps.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "mtcs/voxel/access_map_cache.h"
#include "mtcs/voxel/accessibility_map.h"
#include "mtcs/voxel/octree.h"
#include "mtcs/voxel/part_map.h"
#include "mtcs/voxel/voxel_grid.h"

namespace mtcs::report {

bool has_drilling_part(const mold::MoldSpec& spec) {
  if (!spec.cavity || spec.cavity->is_patch()) return false;
  if (spec.cavity->mesh) return true;
  return spec.cavity->box && (spec.cavity->box->max - spec.cavity->box->min).minCoeff() > 0;
}

mesh::TriangleMesh drilling_part(const mold::MoldSpec& spec) {
  return spec.cavity->mesh ? spec.cavity->mesh->mesh : mesh::box_mesh(*spec.cavity->box);
}

int grid_for(const mesh::TriangleMesh& part, const DrillingMapOptions& options) {
  const geometry::Vec3 size = part.bounds().size();
  const double thinnest = std::max(size.minCoeff(), 1e-9 * size.maxCoeff());
  const double wanted = std::ceil(2 * size.maxCoeff() / thinnest) + 2;  // thinnest ~ two voxels
  return int(std::clamp(wanted, double(options.min_grid), double(options.max_grid)));
}

DrillingMaps drilling_maps(const mold::MoldSpec& spec, const mold::Layout& layout, const DrillingMapOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  DrillingMaps out;
  out.part = spec.cavity->mesh ? "cavity mesh" : "cavity box";
  const mesh::TriangleMesh part = drilling_part(spec);
  out.grid = grid_for(part, options);
  const voxel::GridSpec grid = voxel::part_grid(part, out.grid);
  out.voxel_size = grid.voxel_size;
  const voxel::Octree tree(voxel::voxelize(part, grid));
  out.solid_voxels = tree.solid_voxels();
  out.sphere = {options.rows, options.cols};
  for (const mold::Bore& bore : layout.bores) {
    EntryMap e;
    e.bore = bore.name();
    e.entry = bore.hole.p0;
    const geometry::Vec3 axis = bore.hole.p1 - bore.hole.p0;
    const bool has_axis = axis.norm() > 0;  // a zero-length hole has no direction to mark
    if (has_axis) e.direction = axis.normalized();
    e.radius = bore.diameter / 2;
    e.length = bore.drilled_length;
    e.pivot_inside = voxel::pivot_inside(part, tree, grid, e.entry);
    const auto cells = has_axis ? voxel::cells_of(out.sphere, e.direction) : std::vector<std::array<int, 2>>{};
    if (!cells.empty()) e.cell = cells.front();
    if (e.pivot_inside) {
      e.cells.assign(std::size_t(options.rows) * std::size_t(options.cols), 1);
    } else {
      const voxel::AccessMap map = voxel::compute_access_map(tree, e.entry, voxel::bore_tool(e.radius, e.length), out.sphere);
      e.cells = map.cells;
      e.free_cells = long(map.cells.size()) - map.collisions();
      for (const auto& c : cells)
        if (!map.collides(c[0], c[1])) {
          e.direction_free = true;
          e.cell = c;
          break;
        }
    }
    out.entries.push_back(std::move(e));
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace mtcs::report
