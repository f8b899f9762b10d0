#include "mtcs/thermal/finite_volume.h"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>

#include "fv_geometry.h"
#include "mtcs/mesh/bvh.h"

namespace mtcs::thermal {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr int kSteel = FvField::kSteel, kVoid = FvField::kCavity;  // a channel's cells hold its index

// Face f of the block (BlockFace order) is normal to axis f / 2, at the max end when f is odd.
int face_axis(int face) { return face / 2; }
bool face_is_max(int face) { return face % 2 == 1; }
// The two axes spanning face f's plane, as (b, c).
std::array<int, 2> face_plane_axes(int face) {
  const int a = face_axis(face);
  return {(a + 1) % 3, (a + 2) % 3};
}

// A grid link from a steel cell's centre that enters a bore before reaching its other end.
struct Cut {
  double t;        // distance along the link, mm
  double cosine;   // |n . e| at the wall
  int channel;
};

struct CellRange {
  std::array<int, 3> lo, hi;  // inclusive
};

// floor(u) as an int, clamped to [-2, n + 1]: a far point stays representable.
int clamped_floor(double u, int n) {
  if (!(u > -2)) return -2;
  if (u > n + 1) return n + 1;
  return int(std::floor(u));
}

}  // namespace

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
    base[a] = clamped_floor(u, cells[a]);
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
  for (int a = 0; a < 3; ++a) home[a] = clamped_floor((p[a] - origin[a]) / spacing[a], cells[a]);
  double best = std::numeric_limits<double>::infinity(), value = kNaN;
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
  if (!p.allFinite() || temperature.empty()) return kNaN;
  for (int a = 0; a < 3; ++a)  // more than a cell outside the block: nothing near
    if (p[a] < origin[a] - spacing[a] || p[a] > origin[a] + (cells[a] + 1) * spacing[a]) return kNaN;
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

namespace {

// Builds the grid, the cell kinds and the cut links; then the linear system.
class Grid {
 public:
  Grid(const Model& model, const FvOptions& options, FvField& field) : model_(model), field_(field) {
    const Box& block = model.setting.block;
    const Vec3 size = block.size();
    if (!(size.array() > 0).all() || !size.allFinite())
      throw std::invalid_argument("finite volume: the block must have a positive, finite size");
    if (!(options.cell > 0) || !std::isfinite(options.cell))
      throw std::invalid_argument("finite volume: the cell size must be positive");
    if (!(model.setting.conductivity > 0) || !std::isfinite(model.setting.conductivity))
      throw std::invalid_argument("finite volume: the conductivity must be positive");
    for (int a = 0; a < 3; ++a) {
      const double n = std::max(1.0, std::round(size[a] / options.cell));
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

  int kind(int i, int j, int k) const { return kind_[field_.index(i, j, k)]; }
  bool inside(int i, int j, int k) const {
    return i >= 0 && j >= 0 && k >= 0 && i < field_.cells[0] && j < field_.cells[1] && k < field_.cells[2];
  }
  const Cut* cut(std::size_t cell, int dir) const {
    const auto it = cuts_.find(cell * 6 + std::size_t(dir));
    return it == cuts_.end() ? nullptr : &it->second;
  }

  // The cells whose centres may lie in [lo, hi], grown by `margin` cells, clamped to the grid.
  CellRange range(const Vec3& lo, const Vec3& hi, int margin) const {
    CellRange r;
    for (int a = 0; a < 3; ++a) {
      const double s = field_.spacing[a], o = field_.origin[a];
      const double l = std::floor((lo[a] - o) / s - 0.5) - margin, h = std::ceil((hi[a] - o) / s - 0.5) + margin;
      r.lo[a] = int(std::clamp(l, 0.0, field_.cells[a] - 1.0));
      r.hi[a] = int(std::clamp(h, 0.0, field_.cells[a] - 1.0));
    }
    return r;
  }
  template <class F>
  void for_cells(const CellRange& r, F&& f) const {
    for (int k = r.lo[2]; k <= r.hi[2]; ++k)
      for (int j = r.lo[1]; j <= r.hi[1]; ++j)
        for (int i = r.lo[0]; i <= r.hi[0]; ++i) f(i, j, k);
  }

 private:
  void mark_void() {
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

  geometry::Cylinder cylinder(int c) const {
    const Channel& ch = model_.channels[std::size_t(c)];
    return {ch.axis.p0, ch.axis.p1, ch.radius};
  }
  CellRange channel_range(int c, int margin) const {
    const Channel& ch = model_.channels[std::size_t(c)];
    const Vec3 lo = ch.axis.p0.cwiseMin(ch.axis.p1).array() - ch.radius;
    const Vec3 hi = ch.axis.p0.cwiseMax(ch.axis.p1).array() + ch.radius;
    return range(lo, hi, margin);
  }

  void mark_channels() {
    for (int c = 0; c < int(model_.channels.size()); ++c) {
      const Channel& ch = model_.channels[std::size_t(c)];
      if (!(ch.radius > 0) || !ch.axis.p0.allFinite() || !ch.axis.p1.allFinite() || !std::isfinite(ch.coolant) ||
          !(ch.film > 0))
        throw std::invalid_argument("finite volume: channel " + std::to_string(c) +
                                    " needs a positive radius and film and finite coordinates");
      const geometry::Cylinder cyl = cylinder(c);
      for_cells(channel_range(c, 1), [&](int i, int j, int k) {
        int& kd = kind_[field_.index(i, j, k)];
        if (kd == kSteel && fv::inside_cylinder(field_.centre(i, j, k), cyl)) kd = c;
      });
    }
  }

  // Every link from a steel centre (to the neighbour's centre, or to the block face) that
  // enters a bore: the nearest wall over all channels.
  void cut_links() {
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
          const double length = (inside(n[0], n[1], n[2]) ? 1.0 : 0.5) * field_.spacing[a];
          Vec3 e = Vec3::Zero();
          e[a] = step;
          const auto entry = fv::enter_cylinder(p, e, length, cyl);
          if (!entry) continue;
          const std::size_t key = field_.index(i, j, k) * 6 + std::size_t(dir);
          const auto it = cuts_.find(key);
          if (it == cuts_.end() || entry->t < it->second.t) cuts_[key] = Cut{entry->t, entry->cosine, c};
        }
      });
    }
  }

  const Model& model_;
  FvField& field_;
  std::vector<int> kind_;
  std::unordered_map<std::size_t, Cut> cuts_;
};

// Heat from heat_in: on a block face it goes to the face cells it overlaps (exact area); on the
// walls of a cavity void, to the nearest steel cells (a staircase).
class HeatInput {
 public:
  HeatInput(const Model& model, const Grid& grid, FvField& field, std::vector<double>& source)
      : grid_(grid), field_(field), source_(source) {
    const Box& block = model.setting.block;
    const double scale = std::max(block.min.cwiseAbs().maxCoeff(), block.max.cwiseAbs().maxCoeff());
    tolerance_ = 1e-9 * (1 + scale) + 1e-9 * block.size().maxCoeff();
    for (const HeatedTriangle& t : model.setting.heat_in) {
      if (!std::isfinite(t.flux) || !t.a.allFinite() || !t.b.allFinite() || !t.c.allFinite())
        throw std::invalid_argument("finite volume: a heat_in triangle is not finite");
      const double area = 0.5 * (t.b - t.a).cross(t.c - t.a).norm();
      if (area == 0 || t.flux == 0) continue;
      const int face = block_face_of(t, block);
      if (face >= 0)
        spread_on_face(t, face);
      else
        spread_in_volume(t.a, t.b, t.c, t.flux);
    }
  }
  double total() const { return total_; }  // W, the part of heat_in inside the block

 private:
  int block_face_of(const HeatedTriangle& t, const Box& block) const {
    for (int face = 0; face < 6; ++face) {
      const int a = face_axis(face);
      const double plane = face_is_max(face) ? block.max[a] : block.min[a];
      if (std::abs(t.a[a] - plane) <= tolerance_ && std::abs(t.b[a] - plane) <= tolerance_ &&
          std::abs(t.c[a] - plane) <= tolerance_)
        return face;
    }
    return -1;
  }

  void spread_on_face(const HeatedTriangle& t, int face) {
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
        const double overlap = fv::triangle_rectangle_overlap(pa, pb, pc, b * sb, (b + 1) * sb, c * sc, (c + 1) * sc);
        if (overlap <= 0) continue;
        total_ += overlap * t.flux;  // what lies outside the block does not enter
        std::array<int, 3> ijk{};
        ijk[a] = layer;
        ijk[ab] = b;
        ijk[ac] = c;
        if (grid_.kind(ijk[0], ijk[1], ijk[2]) != kSteel) {  // a bore breaks through here
          deposit(field_.centre(ijk[0], ijk[1], ijk[2]), overlap * t.flux);
          continue;
        }
        const std::size_t f = std::size_t(b) + std::size_t(field_.cells[ab]) * std::size_t(c);
        field_.face_heat[face][f] += overlap * t.flux;
        field_.face_covered[face][f] += overlap;
      }
  }

  // Each cell takes the heat of the part of the triangle inside it (the triangle moved a hair
  // into the steel, so that one on a cell face goes to the steel side). A part in a cavity or
  // channel cell goes to the nearest steel cell, looked for a quarter cell behind the normal.
  void spread_in_volume(const Vec3& a, const Vec3& b, const Vec3& c, double flux) {
    const double h = field_.spacing.minCoeff();
    const Vec3 normal = (b - a).cross(c - a).normalized();
    const Vec3 shift = -1e-6 * h * normal - field_.origin;  // relative to the grid: no cancellation
    const Vec3 ra = a + shift, rb = b + shift, rc = c + shift;
    const Vec3 lo = a.cwiseMin(b).cwiseMin(c), hi = a.cwiseMax(b).cwiseMax(c);
    grid_.for_cells(grid_.range(lo, hi, 1), [&](int i, int j, int k) {
      const Vec3 cell_lo(i * field_.spacing.x(), j * field_.spacing.y(), k * field_.spacing.z());
      const fv::Piece piece = fv::clip_triangle_to_box(ra, rb, rc, cell_lo, cell_lo + field_.spacing);
      if (piece.area <= 0) return;
      total_ += piece.area * flux;
      if (grid_.kind(i, j, k) == kSteel)
        source_[field_.index(i, j, k)] += piece.area * flux;
      else
        deposit(piece.centroid + field_.origin - 0.25 * h * normal, piece.area * flux);
    });
  }

  void deposit(const Vec3& p, double heat) {
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
        return;
      }
    }
    throw std::invalid_argument("finite volume: a heat_in triangle has no steel cell within three cells");
  }

  const Grid& grid_;
  FvField& field_;
  std::vector<double>& source_;
  double tolerance_ = 0;
  double total_ = 0;
};

// A conductance from a steel cell to a fixed temperature (a bore wall or the air), for the
// heat balance.
struct Sink {
  int row;
  double conductance;  // W/K
  double temperature;
  int channel;  // -1 for an outer face
};

template <class Preconditioner>
Eigen::VectorXd conjugate_gradient(const Eigen::SparseMatrix<double>& matrix, const Eigen::VectorXd& rhs,
                                   const Eigen::VectorXd& guess, const FvOptions& options, FvResult& result) {
  const auto start = std::chrono::steady_clock::now();
  Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper, Preconditioner> solver;
  solver.setTolerance(options.tolerance);
  solver.setMaxIterations(options.max_iterations);
  solver.compute(matrix);
  if (solver.info() != Eigen::Success) throw std::runtime_error("finite volume: the preconditioner failed");
  Eigen::VectorXd x = solver.solveWithGuess(rhs, guess);
  result.iterations = int(solver.iterations());
  result.residual = solver.error();
  result.solver_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return x;
}

}  // namespace

FvResult solve_finite_volume(const Model& model, const Samples& samples, const FvOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  FvResult result;
  FvField& field = result.field;
  const Setting& setting = model.setting;
  const double k = setting.conductivity;
  const Grid grid(model, options, field);
  field.conductivity = k;
  field.faces = setting.faces;
  for (int face = 0; face < 6; ++face) {
    if (!(setting.faces[std::size_t(face)].film >= 0) || !std::isfinite(setting.faces[std::size_t(face)].film) ||
        !std::isfinite(setting.faces[std::size_t(face)].ambient))
      throw std::invalid_argument("finite volume: face films must be finite and >= 0");
    const auto [ab, ac] = face_plane_axes(face);
    field.face_heat[std::size_t(face)].assign(std::size_t(field.cells[ab]) * std::size_t(field.cells[ac]), 0.0);
    field.face_covered[std::size_t(face)] = field.face_heat[std::size_t(face)];
  }

  const std::size_t n_cells = std::size_t(field.cells[0]) * field.cells[1] * field.cells[2];
  std::vector<double> source(n_cells, 0.0);
  const HeatInput heat(model, grid, field, source);
  for (int kk = 0; kk < field.cells[2]; ++kk)
    for (int j = 0; j < field.cells[1]; ++j)
      for (int i = 0; i < field.cells[0]; ++i) {
        const std::size_t cell = field.index(i, j, kk);
        if (source[cell] == 0) continue;
        double open = 0;  // area of the faces to the cavity
        for (int dir = 0; dir < 6; ++dir) {
          std::array<int, 3> nb{i, j, kk};
          nb[dir / 2] += dir % 2 ? 1 : -1;
          if (grid.inside(nb[0], nb[1], nb[2]) && grid.kind(nb[0], nb[1], nb[2]) == kVoid)
            open += field.spacing[(dir / 2 + 1) % 3] * field.spacing[(dir / 2 + 2) % 3];
        }
        if (open > 0) field.wall_flux[cell] = source[cell] / open;
      }

  // Number the steel cells.
  std::vector<int> row(n_cells, -1);
  int n = 0;
  for (int kk = 0; kk < field.cells[2]; ++kk)
    for (int j = 0; j < field.cells[1]; ++j)
      for (int i = 0; i < field.cells[0]; ++i)
        if (grid.kind(i, j, kk) == kSteel) row[field.index(i, j, kk)] = n++;
  if (n == 0) throw std::invalid_argument("finite volume: no steel cell (the cell size is too coarse?)");

  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(std::size_t(n) * 7);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
  std::vector<Sink> sinks;
  for (int kk = 0; kk < field.cells[2]; ++kk)
    for (int j = 0; j < field.cells[1]; ++j)
      for (int i = 0; i < field.cells[0]; ++i) {
        const std::size_t cell = field.index(i, j, kk);
        const int r = row[cell];
        if (r < 0) continue;
        const std::array<int, 3> ijk{i, j, kk};
        double diagonal = 0;
        rhs[r] += source[cell];
        for (int dir = 0; dir < 6; ++dir) {
          const int a = dir / 2, step = dir % 2 ? 1 : -1;
          const double area = field.spacing[(a + 1) % 3] * field.spacing[(a + 2) % 3];
          const double h = field.spacing[a];
          std::array<int, 3> nb = ijk;
          nb[a] += step;
          const bool boundary = !grid.inside(nb[0], nb[1], nb[2]);
          const Cut* cut = grid.cut(cell, dir);
          Cut fallback{};
          if (!cut && !boundary && grid.kind(nb[0], nb[1], nb[2]) >= 0) {  // rounding: the centre is in, no entry found
            fallback = Cut{h, 1.0, grid.kind(nb[0], nb[1], nb[2])};
            cut = &fallback;
          }
          if (boundary) {  // the heat entering there, even where a bore cuts the link
            const auto [ab, ac] = face_plane_axes(dir);
            rhs[r] += field.face_heat[std::size_t(dir)][std::size_t(ijk[ab]) + std::size_t(field.cells[ab]) * std::size_t(ijk[ac])];
          }
          if (cut) {
            const Channel& ch = model.channels[std::size_t(cut->channel)];
            // Conduction to the wall in series with the film; a tiny distance is floored so the
            // row stays finite (the cell then sits at the wall's temperature).
            const double distance = std::max(cut->t, 1e-9 * h);
            const double film = std::isinf(ch.film) ? 0.0 : cut->cosine > 0 ? 1 / (ch.film * cut->cosine) : -1;
            const double g = film < 0 ? 0.0 : area / (distance / k + film);
            diagonal += g;
            rhs[r] += g * ch.coolant;
            sinks.push_back({r, g, ch.coolant, cut->channel});
          } else if (boundary) {
            const auto [ab, ac] = face_plane_axes(dir);
            const std::size_t f = std::size_t(ijk[ab]) + std::size_t(field.cells[ab]) * std::size_t(ijk[ac]);
            const FaceCondition& fc = setting.faces[std::size_t(dir)];
            const double open = std::max(0.0, area - field.face_covered[std::size_t(dir)][f]);
            const double g = fc.film > 0 ? open / (0.5 * h / k + 1 / fc.film) : 0.0;
            diagonal += g;
            rhs[r] += g * fc.ambient;
            if (g > 0) sinks.push_back({r, g, fc.ambient, -1});
          } else if (grid.kind(nb[0], nb[1], nb[2]) == kSteel) {
            const double g = k * area / h;
            diagonal += g;
            entries.emplace_back(r, row[field.index(nb[0], nb[1], nb[2])], -g);
          }  // a void neighbour: adiabatic
        }
        entries.emplace_back(r, r, diagonal);
      }
  Eigen::SparseMatrix<double> matrix(n, n);
  matrix.setFromTriplets(entries.begin(), entries.end());
  entries = {};

  // Start from the conductance-weighted mean of the fixed temperatures: the field is near them.
  double guess = 0, weight = 0;
  for (const Sink& s : sinks) guess += s.conductance * s.temperature, weight += s.conductance;
  const Eigen::VectorXd x0 = Eigen::VectorXd::Constant(n, weight > 0 ? guess / weight : 0.0);
  Eigen::VectorXd x;
  if (options.preconditioner == FvPreconditioner::IncompleteCholesky)
    x = conjugate_gradient<Eigen::IncompleteCholesky<double, Eigen::Lower, Eigen::NaturalOrdering<int>>>(
        matrix, rhs, x0, options, result);
  else
    x = conjugate_gradient<Eigen::DiagonalPreconditioner<double>>(matrix, rhs, x0, options, result);
  result.steel_cells = std::size_t(n);

  field.kind.resize(n_cells);
  field.temperature.assign(n_cells, kNaN);
  for (int kk = 0; kk < field.cells[2]; ++kk)
    for (int j = 0; j < field.cells[1]; ++j)
      for (int i = 0; i < field.cells[0]; ++i) {
        const std::size_t cell = field.index(i, j, kk);
        const int kind = grid.kind(i, j, kk);
        field.kind[cell] = kind;
        if (kind == kSteel)
          field.temperature[cell] = x[row[cell]];
        else if (kind >= 0)
          field.temperature[cell] = model.channels[std::size_t(kind)].coolant;
      }

  result.heat_in = heat.total();
  result.heat_to_channel.assign(model.channels.size(), 0.0);
  for (const Sink& s : sinks) {
    const double q = s.conductance * (x[s.row] - s.temperature);
    if (s.channel >= 0)
      result.heat_to_channel[std::size_t(s.channel)] += q;
    else
      result.heat_to_faces += q;
  }
  for (double q : result.heat_to_channel) result.heat_to_channels += q;

  result.temperature.reserve(samples.size());
  for (const Vec3& p : samples.points) result.temperature.push_back(field.temperature_at(p));
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace mtcs::thermal
