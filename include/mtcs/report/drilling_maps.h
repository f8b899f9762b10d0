#pragma once
// The drilling maps of a layout's bore entries for the report page (issue 13): for each bore,
// the accessibility map (mtcs/voxel) of a straight tool of the bore's radius and drilled length
// pivoting at its entry point (where it is drilled from), against the cavity voxelised once.
// What `mtcs access-map PART --pivot ENTRY --bore r,L --grid N --am ROWS,COLS` prints for it.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "mtcs/mold/layout.h"
#include "mtcs/mold/mold_spec.h"
#include "mtcs/voxel/tool.h"

namespace mtcs::report {

struct DrillingMapOptions {
  int min_grid = 64;        // voxels per side at least; more when the part is thin (see grid_for)
  int max_grid = 256;
  int rows = 18, cols = 36;  // 10 x 10 deg cells: enough to read on a small canvas, ~1 ms a map
};

struct EntryMap {
  std::string bore;            // its name (c0.b1)
  geometry::Vec3 entry = geometry::Vec3::Zero();      // where it is drilled from (hole.p0)
  geometry::Vec3 direction = geometry::Vec3::Zero();  // unit, entry -> far end
  double radius = 0, length = 0;  // the tool: the bore's radius and drilled length
  bool pivot_inside = false;   // the entry lies in the part: no map (every cell blocked)
  std::vector<std::uint8_t> cells;  // rows x cols, row-major (phi rows, gamma columns), 1 = blocked
  long free_cells = 0;
  std::array<int, 2> cell{0, 0};  // the bore's own direction's cell (a free one if any holds it)
  bool direction_free = false;
};

struct DrillingMaps {
  std::string part;            // "cavity mesh" or "cavity box"
  int grid = 0;                // voxels per side (voxel::part_grid)
  double voxel_size = 0;       // mm
  std::size_t solid_voxels = 0;
  voxel::SphereGrid sphere;
  std::vector<EntryMap> entries;  // one per bore, in layout order
  double seconds = 0;          // voxelising and every map
};

// The part the maps are drawn against: the cavity's mesh, or its box as a mesh. None when the
// spec has no cavity with volume (no cavity, or a patch on a face).
bool has_drilling_part(const mold::MoldSpec& spec);
mesh::TriangleMesh drilling_part(const mold::MoldSpec& spec);

// Voxels per side for `part`: at least options.min_grid, and enough that its thinnest extent
// spans about two voxels (a 3 mm plate in a 200 mm box would otherwise fall between voxel
// centres and vanish), at most options.max_grid.
int grid_for(const mesh::TriangleMesh& part, const DrillingMapOptions& options);

// Requires has_drilling_part(spec).
DrillingMaps drilling_maps(const mold::MoldSpec& spec, const mold::Layout& layout, const DrillingMapOptions& options = {});

}  // namespace mtcs::report
