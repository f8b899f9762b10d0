// Sampling the solved field: extrapolation to the block faces, interpolation elsewhere.
#include <algorithm>
#include <cmath>
#include <limits>

#include "thermal/fv/fv_grid.h"
#include "mtcs/thermal/finite_volume.h"

namespace mtcs::thermal {

using fv::face_axis;
using fv::face_is_max;
using fv::face_plane_axes;
using fv::kSteel;
using fv::kVoid;

Vec3 FvField::centre(int i, int j, int k) const {
  return origin + Vec3((i + 0.5) * spacing.x(), (j + 0.5) * spacing.y(), (k + 0.5) * spacing.z());
}

bool FvField::is_steel(int i, int j, int k) const {
  if (i < 0 || j < 0 || k < 0 || i >= cells[0] || j >= cells[1] || k >= cells[2]) return false;
  return kind[index(i, j, k)] == kSteel;
}

namespace {

// Whether cell (i, j, k) has a value to interpolate: steel or a channel's.
bool has_value(const FvField& f, int i, int j, int k) {
  if (i < 0 || j < 0 || k < 0 || i >= f.cells[0] || j >= f.cells[1] || k >= f.cells[2]) return false;
  return f.kind[f.index(i, j, k)] != kVoid;
}

}  // namespace

double FvField::face_temperature(int face, int b, int c) const {
  const int a = face_axis(face);
  const auto [ab, ac] = face_plane_axes(face);
  std::array<int, 3> ijk{};
  ijk[a] = face_is_max(face) ? cells[a] - 1 : 0;
  ijk[ab] = b;
  ijk[ac] = c;
  const double t_cell = temperature[index(ijk[0], ijk[1], ijk[2])];
  const double area = spacing[ab] * spacing[ac];
  const std::size_t f = std::size_t(b) + std::size_t(cells[ab]) * std::size_t(c);
  // Per unit area: conduction over the half cell, the heat entering, the film on the uncovered part.
  const double g = conductivity / (0.5 * spacing[a]);
  const double q = face_heat[face][f] / area;
  const double film = faces[face].film * std::max(0.0, 1 - face_covered[face][f] / area);
  return (g * t_cell + q + film * faces[face].ambient) / (g + film);
}

double FvField::interior_temperature(const Vec3& p) const {
  std::array<int, 3> base{};
  std::array<double, 3> frac{};
  for (int a = 0; a < 3; ++a) {
    const double u = (p[a] - origin[a]) / spacing[a] - 0.5;
    base[a] = fv::clamped_floor(u, cells[a]);
    frac[a] = u - base[a];
  }
  double sum = 0, weight = 0;
  for (int corner = 0; corner < 8; ++corner) {
    std::array<int, 3> ijk{};
    double w = 1;
    for (int a = 0; a < 3; ++a) {
      const int up = (corner >> a) & 1;
      ijk[a] = base[a] + up;
      w *= up ? frac[a] : 1 - frac[a];
    }
    if (w > 0 && has_value(*this, ijk[0], ijk[1], ijk[2])) {
      const std::size_t cell = index(ijk[0], ijk[1], ijk[2]);
      double t = temperature[cell];
      if (const auto it = wall_flux.find(cell); it != wall_flux.end()) {
        const double reach = std::min((p - centre(ijk[0], ijk[1], ijk[2])).norm(), 0.5 * spacing.minCoeff());
        t += it->second * reach / conductivity;
      }
      sum += w * t;
      weight += w;
    }
  }
  if (weight > 0) return sum / weight;
  // No steel among the eight: the nearest steel centre within two cells.
  std::array<int, 3> home{};
  for (int a = 0; a < 3; ++a) home[a] = fv::clamped_floor((p[a] - origin[a]) / spacing[a], cells[a]);
  double best = std::numeric_limits<double>::infinity(), value = fv::kNoTemperature;
  for (int dk = -2; dk <= 2; ++dk)
    for (int dj = -2; dj <= 2; ++dj)
      for (int di = -2; di <= 2; ++di) {
        const int i = home[0] + di, j = home[1] + dj, k = home[2] + dk;
        if (!is_steel(i, j, k)) continue;
        const double d = (centre(i, j, k) - p).squaredNorm();
        if (d < best) best = d, value = temperature[index(i, j, k)];
      }
  return value;
}

double FvField::temperature_at(const Vec3& p) const {
  if (!p.allFinite() || temperature.empty()) return fv::kNoTemperature;
  for (int a = 0; a < 3; ++a)  // more than a cell outside the block: nothing near
    if (p[a] < origin[a] - spacing[a] || p[a] > origin[a] + (cells[a] + 1) * spacing[a]) return fv::kNoTemperature;
  for (int face = 0; face < 6; ++face) {
    const int a = face_axis(face);
    const double plane = origin[a] + (face_is_max(face) ? cells[a] * spacing[a] : 0.0);
    if (std::abs(p[a] - plane) > 1e-3 * spacing[a]) continue;
    const auto [ab, ac] = face_plane_axes(face);
    // Bilinear over the face cells' centres, constant beyond the outermost centres.
    std::array<int, 2> lo{}, hi{};
    std::array<double, 2> frac{};
    const std::array<int, 2> axes{ab, ac};
    for (int m = 0; m < 2; ++m) {
      const int n = cells[axes[m]];
      const double u = std::clamp((p[axes[m]] - origin[axes[m]]) / spacing[axes[m]] - 0.5, 0.0, n - 1.0);
      lo[m] = std::min(int(std::floor(u)), n - 1);
      hi[m] = std::min(lo[m] + 1, n - 1);
      frac[m] = u - lo[m];
    }
    const int layer = face_is_max(face) ? cells[a] - 1 : 0;
    double sum = 0, weight = 0;
    for (int corner = 0; corner < 4; ++corner) {
      const int b = corner & 1 ? hi[0] : lo[0], c = corner & 2 ? hi[1] : lo[1];
      const double w = (corner & 1 ? frac[0] : 1 - frac[0]) * (corner & 2 ? frac[1] : 1 - frac[1]);
      std::array<int, 3> ijk{};
      ijk[a] = layer;
      ijk[ab] = b;
      ijk[ac] = c;
      if (w > 0 && has_value(*this, ijk[0], ijk[1], ijk[2])) {
        sum += w * (is_steel(ijk[0], ijk[1], ijk[2]) ? face_temperature(face, b, c)
                                                     : temperature[index(ijk[0], ijk[1], ijk[2])]);
        weight += w;
      }
    }
    if (weight > 0) return sum / weight;
  }
  return interior_temperature(p);
}

}  // namespace mtcs::thermal
