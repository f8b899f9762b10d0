#include "thermal/fv/fv_grid.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "thermal/fv/fv_geometry.h"
#include "mtcs/mesh/bvh.h"

namespace mtcs::thermal::fv {

int clamped_floor(double u, int n) {
  if (!(u > -2)) return -2;
  if (u > n + 1) return n + 1;
  return int(std::floor(u));
}

Grid::Grid(const Model& model, const FvOptions& options, FvField& field) : model_(model), field_(field) {
  const Box& block = model.setting.block;
  const Vec3 size = block.size();
  if (!(size.array() > 0).all() || !size.allFinite())
    throw std::invalid_argument("finite volume: the block must have a positive, finite size");
  if (!(options.cell > 0) || !std::isfinite(options.cell))
    throw std::invalid_argument("finite volume: the cell size must be positive");
  if (!(model.setting.conductivity > 0) || !std::isfinite(model.setting.conductivity))
    throw std::invalid_argument("finite volume: the conductivity must be positive");
  for (int a = 0; a < 3; ++a) {
    const double n = fv_cells_along(size[a], options.cell);
    if (n > 1e5) throw std::invalid_argument("finite volume: too many cells");
    field.cells[a] = int(n);
    field.spacing[a] = size[a] / n;
  }
  field.origin = block.min;
  const double total = double(field.cells[0]) * field.cells[1] * field.cells[2];
  if (total > 2e8) throw std::invalid_argument("finite volume: too many cells");
  kind_.assign(std::size_t(total), kSteel);
  mark_void();
  mark_channels();
  cut_links();
}

CellRange Grid::range(const Vec3& lo, const Vec3& hi, int margin) const {
  CellRange r;
  for (int a = 0; a < 3; ++a) {
    const double s = field_.spacing[a], o = field_.origin[a];
    const double l = std::floor((lo[a] - o) / s - 0.5) - margin,
                 h = std::ceil((hi[a] - o) / s - 0.5) + margin;
    r.lo[a] = int(std::clamp(l, 0.0, field_.cells[a] - 1.0));
    r.hi[a] = int(std::clamp(h, 0.0, field_.cells[a] - 1.0));
  }
  return r;
}

void Grid::mark_void() {
  const Setting& s = model_.setting;
  if (s.cavity_box) {
    for_cells(range(s.cavity_box->min, s.cavity_box->max, 1), [&](int i, int j, int k) {
      if (s.cavity_box->contains(field_.centre(i, j, k))) kind_[field_.index(i, j, k)] = kVoid;
    });
  }
  if (s.cavity_mesh && !s.cavity_mesh->triangles.empty()) {
    const mesh::TriangleBvh bvh(*s.cavity_mesh);
    const Box b = s.cavity_mesh->bounds();
    for_cells(range(b.min, b.max, 1), [&](int i, int j, int k) {
      if (bvh.contains(field_.centre(i, j, k))) kind_[field_.index(i, j, k)] = kVoid;
    });
  }
}

geometry::Cylinder Grid::cylinder(int c) const {
  const Channel& ch = model_.channels[std::size_t(c)];
  return {ch.axis.p0, ch.axis.p1, ch.radius};
}

CellRange Grid::channel_range(int c, int margin) const {
  const Channel& ch = model_.channels[std::size_t(c)];
  const Vec3 lo = ch.axis.p0.cwiseMin(ch.axis.p1).array() - ch.radius;
  const Vec3 hi = ch.axis.p0.cwiseMax(ch.axis.p1).array() + ch.radius;
  return range(lo, hi, margin);
}

void Grid::mark_channels() {
  for (int c = 0; c < int(model_.channels.size()); ++c) {
    const Channel& ch = model_.channels[std::size_t(c)];
    if (!(ch.radius > 0) || !ch.axis.p0.allFinite() || !ch.axis.p1.allFinite() ||
        !std::isfinite(ch.coolant) || !(ch.film > 0))
      throw std::invalid_argument("finite volume: channel " + std::to_string(c) +
                                  " needs a positive radius and film and finite coordinates");
    const geometry::Cylinder cyl = cylinder(c);
    for_cells(channel_range(c, 1), [&](int i, int j, int k) {
      int& kd = kind_[field_.index(i, j, k)];
      if (kd == kSteel && inside_cylinder(field_.centre(i, j, k), cyl)) kd = c;
    });
  }
}

// Every link from a steel centre (to the neighbour's centre, or to the block face) that
// enters a bore: the nearest wall over all channels.
void Grid::cut_links() {
  const auto keep = [&](std::size_t cell, int dir, double t, double cosine, int c) {
    const std::size_t key = cell * 6 + std::size_t(dir);
    const auto it = cuts_.find(key);
    if (it == cuts_.end() || t < it->second.t) cuts_[key] = Cut{t, cosine, c};
  };
  for (int c = 0; c < int(model_.channels.size()); ++c) {
    const geometry::Cylinder cyl = cylinder(c);
    for_cells(channel_range(c, 2), [&](int i, int j, int k) {
      if (kind(i, j, k) != kSteel) return;
      const Vec3 p = field_.centre(i, j, k);
      const std::array<int, 3> ijk{i, j, k};
      for (int dir = 0; dir < 6; ++dir) {
        const int a = dir / 2, step = dir % 2 ? 1 : -1;
        std::array<int, 3> n = ijk;
        n[a] += step;
        const bool in_grid = inside(n[0], n[1], n[2]);
        const bool steel_neighbour = in_grid && kind(n[0], n[1], n[2]) == kSteel;
        // A link between two steel cells is decided once, from its lower end, for both ends:
        // rounding could otherwise cut it at one end only, and the matrix would lose symmetry.
        if (steel_neighbour && step < 0) continue;
        const double length = (in_grid ? 1.0 : 0.5) * field_.spacing[a];
        Vec3 e = Vec3::Zero();
        e[a] = step;
        const auto entry = enter_cylinder(p, e, length, cyl);
        if (!entry) continue;
        keep(field_.index(i, j, k), dir, entry->t, entry->cosine, c);
        if (steel_neighbour)
          keep(field_.index(n[0], n[1], n[2]), dir - 1, std::max(length - entry->exit, 0.0),
               entry->exit_cosine, c);
      }
    });
  }
}

}  // namespace mtcs::thermal::fv
