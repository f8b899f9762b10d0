#pragma once
// Which drilling directions are free at a bore's entry point: the accessibility map of the bore
// as a tool (radius + the part clearance, its drilled length) pivoting at its entry, against the
// voxelised cavity mesh (mtcs/voxel). Entry points are rounded to multiples of
// `drilling.access_map.entry_step` on every axis and lengths up to the next multiple, so bores
// entering near one another share a map; maps are kept (voxel::AccessMapCache), thread-safe and
// the same for any thread count.
//
// A bore is drillable when its direction (entry -> far end) lies in a free cell of that map
// (voxel::cells_of, closed cells: a direction on a border, such as an axis-parallel bore's, lies
// in the cells on both sides); the map's verdict for a cell's centre direction stands for the
// whole cell, so the verdict is as fine as the map (32 x 32: centres up to ~4 deg off).

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "mtcs/mold/layout.h"
#include "mtcs/mold/scene.h"
#include "mtcs/voxel/access_map_cache.h"

namespace mtcs::eval {

// A bore's verdict with its evidence: the map, its cell, and what `mtcs access-map` needs to
// draw the same map.
struct DrillVerdict {
  bool free = false;
  bool pivot_inside = false;         // the entry lies in a solid voxel: no direction is free
  std::array<int, 2> cell{0, 0};     // row, column of the bore's direction (a free one if any)
  int rows = 0, cols = 0;
  long free_cells = 0;
  double angle_to_free_deg = 180;    // from the bore's direction to the nearest free cell's centre
  geometry::Vec3 pivot = geometry::Vec3::Zero();          // the rounded entry, spec coordinates
  geometry::Vec3 pivot_in_mesh = geometry::Vec3::Zero();  // minus the cavity's translate
  double tool_radius = 0, tool_length = 0;
  geometry::Vec3 direction = geometry::Vec3::Zero();
  std::shared_ptr<const voxel::AccessMap> map;
};

// A free direction of a map, with its cell.
struct FreeDirection {
  std::array<int, 2> cell;
  geometry::Vec3 direction;
};

// "free, cell (15, 0) of 32 x 32 (812 free), pivot (0, 40, 30), tool r 12 mm x 85 mm".
std::string describe(const DrillVerdict& v);

class DrillAccess {
 public:
  // Needs spec().drilling.access_map and a cavity mesh.
  explicit DrillAccess(const mold::Scene& scene);

  DrillVerdict check(const mold::Bore& bore) const;
  // The verdict for a bore of `diameter` drilled from `entry` along `direction`, `length` long.
  DrillVerdict check(const geometry::Vec3& entry, const geometry::Vec3& direction, double diameter, double length) const;
  // The free cells of that bore's map whose centre direction enters `face` within the spec's
  // drilling.max_angle_deg (and points into the block), in row-major order.
  std::vector<FreeDirection> free_directions(const geometry::Vec3& entry, mold::Face face, double diameter, double length) const;

  // `mtcs access-map CAVITY_MESH --pivot ... --bore r,L --grid N --am R,C --out am.png`: the
  // same map, drawn (CheckBox by default there: an independent method).
  std::string access_map_command(const DrillVerdict& v) const;

  const mold::AccessMapSpec& spec() const { return spec_; }
  const voxel::AccessMapCache& cache() const { return cache_; }

 private:
  std::shared_ptr<const voxel::AccessMap> map(const geometry::Vec3& pivot, double radius, double length) const;
  geometry::Vec3 rounded(const geometry::Vec3& entry) const;
  double tool_radius(double diameter) const;
  double tool_length(double length) const;

  const mold::Scene& scene_;
  mold::AccessMapSpec spec_;
  voxel::AccessMapCache cache_;
};

}  // namespace mtcs::eval
