#include "thermal/fv/fv_heat_input.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "thermal/fv/fv_geometry.h"

namespace mtcs::thermal::fv {

HeatInput::HeatInput(const Model& model, const Grid& grid, FvField& field, std::vector<double>& source)
    : grid_(grid), field_(field), source_(source) {
  const Box& block = model.setting.block;
  const double scale = std::max(block.min.cwiseAbs().maxCoeff(), block.max.cwiseAbs().maxCoeff());
  tolerance_ = 1e-9 * (1 + scale) + 1e-9 * block.size().maxCoeff();
  conductivity_ = model.setting.conductivity;
  for (const HeatedTriangle& t : model.setting.heat_in) {
    if (!std::isfinite(t.flux) || !std::isfinite(t.film) || !(t.film >= 0) || !std::isfinite(t.part_temperature) ||
        !t.a.allFinite() || !t.b.allFinite() || !t.c.allFinite())
      throw std::invalid_argument("finite volume: a heat_in triangle is not finite (or its film is negative)");
    const double area = 0.5 * (t.b - t.a).cross(t.c - t.a).norm();
    if (area == 0 || !t.heats()) continue;
    const int face = block_face_of(t, block);
    if (face >= 0)
      spread_on_face(t, face);
    else
      spread_in_volume(t);
  }
}

void HeatInput::add_film(std::size_t cell, double area, double distance, const HeatedTriangle& t) {
  if (!(t.film > 0) || !(area > 0)) return;
  films_.push_back({cell, area / (1 / t.film + distance / conductivity_), t.part_temperature});
}

int HeatInput::block_face_of(const HeatedTriangle& t, const Box& block) const {
  for (int face = 0; face < 6; ++face) {
    const int a = face_axis(face);
    const double plane = face_is_max(face) ? block.max[a] : block.min[a];
    if (std::abs(t.a[a] - plane) <= tolerance_ && std::abs(t.b[a] - plane) <= tolerance_ &&
        std::abs(t.c[a] - plane) <= tolerance_)
      return face;
  }
  return -1;
}

void HeatInput::spread_on_face(const HeatedTriangle& t, int face) {
  const int a = face_axis(face);
  const auto [ab, ac] = face_plane_axes(face);
  const Vec3 ra = t.a - field_.origin, rb = t.b - field_.origin, rc = t.c - field_.origin;
  const double pa[2] = {ra[ab], ra[ac]}, pb[2] = {rb[ab], rb[ac]}, pc[2] = {rc[ab], rc[ac]};
  const Vec3 lo = t.a.cwiseMin(t.b).cwiseMin(t.c), hi = t.a.cwiseMax(t.b).cwiseMax(t.c);
  const CellRange r = grid_.range(lo, hi, 1);
  const double sb = field_.spacing[ab], sc = field_.spacing[ac];
  const int layer = face_is_max(face) ? field_.cells[a] - 1 : 0;
  for (int c = r.lo[ac]; c <= r.hi[ac]; ++c)
    for (int b = r.lo[ab]; b <= r.hi[ab]; ++b) {
      const double overlap =
          triangle_rectangle_overlap(pa, pb, pc, b * sb, (b + 1) * sb, c * sc, (c + 1) * sc);
      if (overlap <= 0) continue;
      total_ += overlap * t.flux;  // what lies outside the block does not enter
      std::array<int, 3> ijk{};
      ijk[a] = layer;
      ijk[ab] = b;
      ijk[ac] = c;
      if (grid_.kind(ijk[0], ijk[1], ijk[2]) != kSteel) {  // a bore breaks through here
        Vec3 inward = Vec3::Zero();
        inward[a] = face_is_max(face) ? -1 : 1;
        deposit(field_.centre(ijk[0], ijk[1], ijk[2]), overlap * t.flux, overlap, t, inward);
        continue;
      }
      const std::size_t f = std::size_t(b) + std::size_t(field_.cells[ab]) * std::size_t(c);
      field_.face_heat[face][f] += overlap * t.flux;
      field_.face_covered[face][f] += overlap;
      if (t.film > 0) {
        add_film(field_.index(ijk[0], ijk[1], ijk[2]), overlap, 0.5 * field_.spacing[a], t);
        films_.back().face = face, films_.back().face_cell = f;
      }
    }
}

// Each cell takes the heat of the part of the triangle inside it (the triangle moved a hair
// into the steel, so that one on a cell face goes to the steel side). A part in a cavity or
// channel cell goes to the nearest steel cell, looked for a quarter cell behind the normal.
void HeatInput::spread_in_volume(const HeatedTriangle& t) {
  const Vec3 &a = t.a, &b = t.b, &c = t.c;
  const double flux = t.flux;
  const double h = field_.spacing.minCoeff();
  const Vec3 normal = (b - a).cross(c - a).normalized();
  const Vec3 shift = -1e-6 * h * normal - field_.origin;  // relative to the grid: no cancellation
  const Vec3 ra = a + shift, rb = b + shift, rc = c + shift;
  const Vec3 lo = a.cwiseMin(b).cwiseMin(c), hi = a.cwiseMax(b).cwiseMax(c);
  grid_.for_cells(grid_.range(lo, hi, 1), [&](int i, int j, int k) {
    const Vec3 cell_lo(i * field_.spacing.x(), j * field_.spacing.y(), k * field_.spacing.z());
    const Piece piece = clip_triangle_to_box(ra, rb, rc, cell_lo, cell_lo + field_.spacing);
    if (piece.area <= 0) return;
    total_ += piece.area * flux;
    if (grid_.kind(i, j, k) == kSteel) {
      source_[field_.index(i, j, k)] += piece.area * flux;
      // The film in series with the steel from the wall to the cell's centre.
      add_film(field_.index(i, j, k), piece.area,
               std::abs(normal.dot(field_.centre(i, j, k) - (piece.centroid + field_.origin))), t);
    } else {
      deposit(piece.centroid + field_.origin - 0.25 * h * normal, piece.area * flux, piece.area, t, -normal);
    }
  });
}

// `steel`: the wall's normal into the steel, for the film's distance to the cell's centre.
void HeatInput::deposit(const Vec3& p, double heat, double area, const HeatedTriangle& t, const Vec3& steel) {
  std::array<int, 3> home{};
  for (int a = 0; a < 3; ++a)
    home[a] = std::clamp(clamped_floor((p[a] - field_.origin[a]) / field_.spacing[a], field_.cells[a]), 0,
                         field_.cells[a] - 1);
  for (int reach = 0; reach <= 3; ++reach) {
    double best = std::numeric_limits<double>::infinity();
    std::size_t cell = 0;
    for (int dk = -reach; dk <= reach; ++dk)
      for (int dj = -reach; dj <= reach; ++dj)
        for (int di = -reach; di <= reach; ++di) {
          const int i = home[0] + di, j = home[1] + dj, k = home[2] + dk;
          if (!grid_.inside(i, j, k) || grid_.kind(i, j, k) != kSteel) continue;
          const double d = (field_.centre(i, j, k) - p).squaredNorm();
          if (d < best) best = d, cell = field_.index(i, j, k);
        }
    if (best < std::numeric_limits<double>::infinity()) {
      source_[cell] += heat;
      const Vec3 centre = field_.centre(int(cell % std::size_t(field_.cells[0])),
                                        int(cell / std::size_t(field_.cells[0]) % std::size_t(field_.cells[1])),
                                        int(cell / (std::size_t(field_.cells[0]) * std::size_t(field_.cells[1]))));
      add_film(cell, area, std::abs(steel.dot(centre - p)), t);
      return;
    }
  }
  throw std::invalid_argument("finite volume: a heat_in triangle has no steel cell within three cells");
}

}  // namespace mtcs::thermal::fv
