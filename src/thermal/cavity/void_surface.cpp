#include "thermal/cavity/void_surface.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <map>
#include <numbers>
#include <stdexcept>
#include <tuple>

#include <tbb/parallel_for.h>

#include "mtcs/geometry/triangle_distance.h"
#include "thermal/cavity/panel_matrix_cache.h"
#include "thermal/kernels/cpu_features.h"
#include "thermal/linalg/skinny_product.h"

namespace mtcs::thermal {

namespace {

// Panel j's layer within kPoints of its radius: per sub-triangle, exactly within kNearSub
// (kNearSubGradient for the gradient, whose point error (size / distance)^2 weighs more across
// a thin void) of the sub-triangle's size, else as a point; beyond, the panel as one point, relative error
// below (radius / distance)^2, ~1.5 % (the layer's dipole about the centroid vanishes). Pairs
// of panels within kExact radii hold the condition for the flux through the panel.
constexpr double kExact = 3, kPoints = 8, kNearSub = 3, kNearSubGradient = 6;
// ~N^2 of memory (N = 3000: 72 MB in double, with the inverse in float), N^3 / 3 for the LU.
constexpr double kMaxPanels = 3000;
// The flux through a panel from a panel across an edge of the wall (normals 60 degrees or more
// apart) is singular where they meet: its pieces are halved while wider than their distance to
// the other panel, kGradedDepth times at most. At one point per sub-triangle the cup's core ran
// 29 K too cold on average (its heat leaked round the wall's edges into the bores outside);
// at depths 3, 4, 5: 8, 6, 5 K (experiments/thermal/void_surface.md, section 6).
constexpr int kGradedDepth = 4;
// Faces of the wall closer than this many panels end their panels at one plane; at most
// kMaxFacePlanes faces' planes per axis.
constexpr double kMergePlanes = 0.05;
constexpr std::size_t kMaxFacePlanes = 64;

// Per axis, the planes where panels end: those of the wall's faces normal to the axis that lie
// less than a panel from another such face (the two faces of a wall thinner than a panel), and
// between them equal steps no wider than `panel`. Where a thin shell turns a corner, its outer
// face runs a wall's thickness past the inner one. In cells blind to the faces, a panel on one
// face then had a shorter partner across the void, and the cup's field dipped up to 60 K below
// T3 along the part's outer edges (experiments/thermal/void_surface.md, section 7). Ending the
// panels at the faces' planes pairs them, and the corner's strip is a panel of its own. More
// than kMaxFacePlanes such planes on an axis: none on it (the panels' count stays bounded).
// `lo`, `hi`: the wall's bounding box.
std::array<std::vector<double>, 3> panel_planes(std::span<const HeatedTriangle> wall, double panel, const Vec3& lo,
                                                const Vec3& hi) {
  std::array<std::vector<double>, 3> faces, planes;
  for (const HeatedTriangle& t : wall) {
    const Vec3 n = (t.b - t.a).cross(t.c - t.a);
    const double length = n.norm();
    for (int axis = 0; axis < 3; ++axis)
      if (length > 0 && std::abs(n[axis]) >= (1 - 1e-9) * length) faces[std::size_t(axis)].push_back(t.a[axis]);
  }
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<double>& f = faces[std::size_t(axis)];
    std::sort(f.begin(), f.end());
    f.erase(std::unique(f.begin(), f.end(), [&](double a, double b) { return b - a <= kMergePlanes * panel; }), f.end());
    std::vector<double> kept{lo[axis]};
    for (std::size_t i = 0; i < f.size(); ++i) {
      const bool thin = (i > 0 && f[i] - f[i - 1] < panel) || (i + 1 < f.size() && f[i + 1] - f[i] < panel);
      if (thin && f[i] - kept.back() > kMergePlanes * panel) kept.push_back(f[i]);
    }
    if (kept.size() > kMaxFacePlanes + 1) kept.erase(kept.begin() + 1, kept.end());
    if (hi[axis] - kept.back() > kMergePlanes * panel) kept.push_back(hi[axis]);
    else kept.back() = hi[axis];
    std::vector<double>& at = planes[std::size_t(axis)];
    for (std::size_t i = 0; i + 1 < kept.size(); ++i) {
      const int steps = std::max(1, int(std::ceil((kept[i + 1] - kept[i]) / panel - 1e-9)));
      for (int s = 1; s < steps; ++s) at.push_back(kept[i] + (kept[i + 1] - kept[i]) * s / steps);
      if (i + 2 < kept.size()) at.push_back(kept[i + 1]);  // the ends divide nothing
    }
  }
  return planes;
}

// Triangle t cut by the planes into convex pieces, each within one cell.
std::vector<std::vector<Vec3>> cut_at_planes(const HeatedTriangle& t, const std::array<std::vector<double>, 3>& planes) {
  std::vector<std::vector<Vec3>> pieces{{t.a, t.b, t.c}}, next;
  for (int axis = 0; axis < 3; ++axis)
    for (const double x : planes[std::size_t(axis)]) {
      next.clear();
      for (std::vector<Vec3>& p : pieces) {
        double lo = p[0][axis], hi = lo;
        for (const Vec3& v : p) lo = std::min(lo, v[axis]), hi = std::max(hi, v[axis]);
        if (!(lo < x && x < hi)) {
          next.push_back(std::move(p));
          continue;
        }
        std::vector<Vec3> below, above;
        for (std::size_t i = 0; i < p.size(); ++i) {
          const Vec3 &u = p[i], &v = p[(i + 1) % p.size()];
          if (u[axis] <= x) below.push_back(u);
          if (u[axis] >= x) above.push_back(u);
          if ((u[axis] < x && v[axis] > x) || (u[axis] > x && v[axis] < x)) {
            const Vec3 w = u + (x - u[axis]) / (v[axis] - u[axis]) * (v - u);
            below.push_back(w), above.push_back(w);
          }
        }
        if (below.size() >= 3) next.push_back(std::move(below));
        if (above.size() >= 3) next.push_back(std::move(above));
      }
      pieces.swap(next);
    }
  return pieces;
}

}  // namespace

VoidSurface::VoidSurface(std::span<const HeatedTriangle> wall, std::span<const Image> images, double panel,
                         double conductivity, const FarLattice& far, bool on_block_face)
    : images_(images.begin(), images.end()), conductivity_(conductivity), on_block_face_(on_block_face) {
  if (!(panel > 0)) throw std::invalid_argument("cavity void: the panel size must be > 0");
  // At most kMaxPanels panels: the dense solve costs panels^3 once and panels^2 per new bore.
  double area = 0;
  for (const HeatedTriangle& t : wall) area += 0.5 * (t.b - t.a).cross(t.c - t.a).norm();
  panel = std::max(panel, std::sqrt(area / kMaxPanels));
  panel_ = panel;
  // The wall's triangles cut at the panel planes (panel_planes), the pieces into sub-triangles
  // half a panel wide or less, gathered per cell of the planes and per direction of the steel's
  // normal (a thin shell's two faces apart).
  struct Cut {
    std::vector<Sub> subs;
    Vec3 normal_sum = Vec3::Zero();
  };
  std::map<std::tuple<long, long, long, int>, Cut> cells;  // ordered: the same panels every time
  Vec3 origin = Vec3::Constant(std::numeric_limits<double>::infinity()), top = -origin;
  for (const HeatedTriangle& t : wall)
    origin = origin.cwiseMin(t.a).cwiseMin(t.b).cwiseMin(t.c), top = top.cwiseMax(t.a).cwiseMax(t.b).cwiseMax(t.c);
  far_.origin = origin;
  const std::array<std::vector<double>, 3> planes = panel_planes(wall, panel, origin, top);
  auto cell = [&](const Vec3& p, int axis) {
    const std::vector<double>& at = planes[std::size_t(axis)];
    return long(std::upper_bound(at.begin(), at.end(), p[axis]) - at.begin());
  };
  for (const HeatedTriangle& t : wall) {
    const Vec3 twice = (t.b - t.a).cross(t.c - t.a);
    if (twice.norm() == 0) continue;
    const Vec3 steel = -twice.normalized();  // heat_in faces the void
    int axis = 0;
    steel.cwiseAbs().maxCoeff(&axis);
    const int direction = 2 * axis + (steel[axis] > 0);
    auto add = [&](const Vec3& a, const Vec3& b, const Vec3& c) {
      const Vec3 centroid = (a + b + c) / 3;
      Cut& cut = cells[{cell(centroid, 0), cell(centroid, 1), cell(centroid, 2), direction}];
      const TriangleSource source(a, b, c);
      cut.subs.push_back({source, centroid, source.area(), t.flux, t.film, t.part_temperature});
      cut.normal_sum += source.area() * steel;
    };
    for (const std::vector<Vec3>& piece : cut_at_planes(t, planes))
      for (std::size_t f = 1; f + 1 < piece.size(); ++f) {  // a convex piece, as a fan
        const Vec3 &a = piece[0], &b = piece[f], &c = piece[f + 1];
        if ((b - a).cross(c - a).norm() <= 1e-12 * twice.norm()) continue;
        const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
        const int k = std::max(1, int(std::ceil(2 * longest / panel)));
        auto at = [&](double u, double v) { return Vec3(a + (u / k) * (b - a) + (v / k) * (c - a)); };
        for (int i = 0; i < k; ++i)
          for (int j = 0; j < k - i; ++j) {
            add(at(i, j), at(i + 1, j), at(i, j + 1));
            if (j + 1 < k - i) add(at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
          }
      }
  }
  if (cells.empty()) throw std::invalid_argument("cavity void: the wall has no area");
  std::vector<double> film, part;
  std::size_t subs = 0;
  for (const auto& [key, cut] : cells) subs += cut.subs.size();
  sub_.reserve(subs);
  for (auto& [key, cut] : cells) {
    double area = 0, heat = 0, conductance = 0, drive = 0;
    Vec3 weighted = Vec3::Zero();
    for (const Sub& s : cut.subs) {
      area += s.area, heat += s.area * s.flux, weighted += s.area * s.centroid;
      conductance += s.area * s.film, drive += s.area * s.film * s.part;
    }
    film.push_back(conductance / area);
    part.push_back(conductance > 0 ? drive / conductance : 0.0);
    const Vec3 centroid = weighted / area;
    // Collocated at the sub-triangle nearest the centroid: a point on the wall, its normal.
    const Sub* best = &cut.subs.front();
    for (const Sub& s : cut.subs)
      if ((s.centroid - centroid).squaredNorm() < (best->centroid - centroid).squaredNorm()) best = &s;
    double radius = 0;
    for (const Sub& s : cut.subs) radius = std::max(radius, (s.centroid - centroid).norm() + std::sqrt(2 * s.area));
    point_.push_back(best->centroid);
    normal_.push_back(-best->source.normal());
    centroid_.push_back(centroid);
    area_.push_back(area);
    radius_.push_back(radius);
    double reach = 0;
    for (const Sub& s : cut.subs)
      for (int k = 0; k < 3; ++k) reach = std::max(reach, (s.source.corner(k) - centroid).norm());
    corner_reach_.push_back(reach);
    flux_.push_back(heat / area);
    Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
    for (const Sub& s : cut.subs) second += s.area * (s.centroid - centroid) * (s.centroid - centroid).transpose();
    constexpr double kFar = 4;  // radii: potential_row's far panels
    const Vec3 local = centroid - origin;
    far_.cx.push_back(float(local.x())), far_.cy.push_back(float(local.y())), far_.cz.push_back(float(local.z()));
    far_.area.push_back(float(area)), far_.far2.push_back(float(kFar * kFar * radius * radius));
    far_.xx.push_back(float(second(0, 0))), far_.yy.push_back(float(second(1, 1))), far_.zz.push_back(float(second(2, 2)));
    far_.xy.push_back(float(second(0, 1))), far_.xz.push_back(float(second(0, 2))), far_.yz.push_back(float(second(1, 2)));
    far_.trace.push_back(float(second.trace()));
    sub_.insert(sub_.end(), std::make_move_iterator(cut.subs.begin()), std::make_move_iterator(cut.subs.end()));
    begin_.push_back(sub_.size());
  }

  // A = 1/2 - K', row by row in parallel (each row its own); kept by the panels' geometry and
  // the images (panel_matrix_cache.h).
  const std::size_t n = panels();
  const auto N = Eigen::Index(n);
  {  // every input of the panels' matrices, hashed once (a 75 000-triangle part: 1.3 M numbers)
    io::CacheKey inputs("void-panels");
    std::vector<double> numbers{panel_, far_.origin.x(), far_.origin.y(), far_.origin.z()};  // the float pass's origin
    numbers.reserve(4 + 9 * sub_.size() + 7 * images_.size());
    for (const Sub& s : sub_)
      for (int k = 0; k < 3; ++k) numbers.insert(numbers.end(), s.source.corner(k).data(), s.source.corner(k).data() + 3);
    for (const Image& g : images_) {
      numbers.insert(numbers.end(), g.mult.data(), g.mult.data() + 3);
      numbers.insert(numbers.end(), g.offset.data(), g.offset.data() + 3);
      numbers.push_back(g.sign);
    }
    inputs.add_values(std::span<const std::size_t>(begin_)).add_values(std::span<const double>(numbers));
    panels_digest_ = inputs.digest();
  }
  Eigen::MatrixXd A;
  if (on_block_face) {
    A = Eigen::MatrixXd::Identity(N, N);
  } else {
    io::CacheKey key = panel_matrix_key("panel-matrix");
    add_panels(key);
    A = *kept_panel_matrix(key, N, N, Keep::disk, [&](Eigen::MatrixXd& a) { assemble(a); });
  }
  // The heat input's sheets (q / k per panel) seen from the void side: (1/2 + K') q / k = (I - A) q / k.
  Eigen::VectorXd q(N);
  for (std::size_t j = 0; j < n; ++j) q[Eigen::Index(j)] = flux_[j] / conductivity;
  heat_d_ = on_block_face ? Eigen::VectorXd::Zero(N) : Eigen::VectorXd(q - A * q);
  film_over_k_ = Eigen::Map<const Eigen::VectorXd>(film.data(), N) / conductivity;
  part_ = Eigen::Map<const Eigen::VectorXd>(part.data(), N);
  robin_ = film_over_k_.maxCoeff() > 0;
  if (robin_) {
    if (!far.kernel) throw std::invalid_argument("cavity void: a wall with a film needs the far lattice");
    moments_.resize(4, N);
    Eigen::MatrixXd F(N, 4);
    for (std::size_t j = 0; j < n; ++j) {
      moments_.col(Eigen::Index(j)) << conductivity * area_[j], conductivity * area_[j] * (centroid_[j] - far.center);
      F.row(Eigen::Index(j)) = far.kernel(point_[j]).transpose();
    }
    A += film_over_k_.asDiagonal() * (*kept_potentials(point_, Keep::disk) + F * moments_);
  }
  lu_.compute(A);
  heat_tau_ = lu_.solve(heat_d_);
  inverse_transposed_ = lu_.inverse().transpose().cast<float>();
}

void VoidSurface::add_panels(io::CacheKey& key) const {
  key.add_values(std::span<const unsigned char>(panels_digest_));
}

void VoidSurface::assemble(Eigen::MatrixXd& A) const {
  const std::size_t n = panels();
  const double inv4pi = 1 / (4 * std::numbers::pi);
  // Near pairs: the flux through panel i (its sub-triangles' centroids, area-weighted; graded
  // toward a panel across an edge of the wall), not the normal derivative at one point: across
  // a thin shell's void, the two faces' panels see each other at nearly a half space, and only
  // the flux keeps the small difference that matters.
  tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
    for (std::size_t j = 0; j < n; ++j) {
      const double reach = kExact * radius_[j] + radius_[i];
      double v;
      if ((centroid_[i] - centroid_[j]).squaredNorm() < reach * reach) {
        v = 0;
        for (std::size_t s = begin_[i]; s < begin_[i + 1]; ++s) {
          const Vec3 steel = -sub_[s].source.normal();
          if (std::abs(normal_[i].dot(normal_[j])) < 0.5) {
            const TriangleSource& t = sub_[s].source;
            v += graded_flux(j, t.corner(0), t.corner(1), t.corner(2), steel, 0);
          } else {
            v += sub_[s].area * panel_gradient(j, sub_[s].centroid, steel);
          }
        }
        v /= area_[i];
      } else {
        v = panel_gradient(j, point_[i], normal_[i]);
      }
      A(Eigen::Index(i), Eigen::Index(j)) = -inv4pi * v;
    }
    A(Eigen::Index(i), Eigen::Index(i)) += 0.5;
  });
}

double VoidSurface::distance_to_panel(std::size_t j, const Vec3& x) const {
  double d = std::numeric_limits<double>::infinity();
  for (std::size_t s = begin_[j]; s < begin_[j + 1]; ++s)
    d = std::min(d, std::max(0.0, (x - sub_[s].centroid).norm() - std::sqrt(2 * sub_[s].area)));
  return d;
}

double VoidSurface::graded_flux(std::size_t j, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& steel,
                                int depth) const {
  const Vec3 centroid = (a + b + c) / 3;
  const double area = 0.5 * (b - a).cross(c - a).norm();
  if (depth < kGradedDepth && std::sqrt(2 * area) > distance_to_panel(j, centroid)) {
    const Vec3 ab = 0.5 * (a + b), bc = 0.5 * (b + c), ca = 0.5 * (c + a);
    return graded_flux(j, a, ab, ca, steel, depth + 1) + graded_flux(j, ab, b, bc, steel, depth + 1) +
           graded_flux(j, ca, bc, c, steel, depth + 1) + graded_flux(j, ab, bc, ca, steel, depth + 1);
  }
  return area * panel_gradient(j, centroid, steel);
}

double VoidSurface::near_potential(std::size_t j, const Vec3& p) const {
  double v = 0;
  for (std::size_t s = begin_[j]; s < begin_[j + 1]; ++s) {
    const Vec3 q = p - sub_[s].centroid;
    const double e2 = q.squaredNorm();
    v += e2 < kNearSub * kNearSub * 2 * sub_[s].area ? sub_[s].source.potential(p) : sub_[s].area / std::sqrt(e2);
  }
  return v;
}

namespace {

// One image's pass over all panels: beyond far2 (kFar radii) a panel's charge and second moment
// (its first moment about the centroid vanishes), relative error ~(R / d)^3 / 2, under 1 %:
// 1 / |r - y| summed = A / d + (3 r^T M' r / d^2 - tr M) / (2 d^3), M' the moment mirrored as
// the image is (off-diagonal signs s). acc[j] += sign * that where far; near[j] = 1 where not.
// In float, coordinates from the wall's corner: r to ~1e-7 of the block's size, a relative
// error of ~1e-6 at kFar radii, below the expansion's own and below the float layer's.
#define MTCS_FAR_PASS_BODY                                                                           \
  const float px = p[0], py = p[1], pz = p[2], sxy = s[0], sxz = s[1], syz = s[2];                  \
  const float *__restrict cx = f.cx, *__restrict cy = f.cy, *__restrict cz = f.cz;                   \
  const float *__restrict area = f.area, *__restrict far2 = f.far2, *__restrict trace = f.trace;     \
  const float *__restrict xx = f.xx, *__restrict yy = f.yy, *__restrict zz = f.zz;                   \
  const float *__restrict xy = f.xy, *__restrict xz = f.xz, *__restrict yz = f.yz;                   \
  _Pragma("GCC ivdep") for (std::size_t j = 0; j < n; ++j) {                                         \
    const float rx = px - cx[j], ry = py - cy[j], rz = pz - cz[j];                                   \
    const float d2 = rx * rx + ry * ry + rz * rz;                                                    \
    const float inv = 1 / std::sqrt(d2), inv2 = inv * inv;                                           \
    const float q = xx[j] * rx * rx + yy[j] * ry * ry + zz[j] * rz * rz +                            \
                    2 * (sxy * xy[j] * rx * ry + sxz * xz[j] * rx * rz + syz * yz[j] * ry * rz);     \
    const float v = area[j] * inv + 0.5f * inv * inv2 * (3 * q * inv2 - trace[j]);                  \
    const bool is_near = d2 < far2[j];                                                               \
    acc[j] += is_near ? 0.0f : sign * v;                                                             \
    near[j] = is_near ? 1.0f : 0.0f;                                                                 \
  }

struct FarColumns {
  const float *cx, *cy, *cz, *area, *far2, *xx, *yy, *zz, *xy, *xz, *yz, *trace;
};

__attribute__((target("avx2,fma"))) void far_pass_avx2(const FarColumns& f, std::size_t n, const float* p,
                                                       const float* s, float sign, float* __restrict acc,
                                                       float* __restrict near) {
  MTCS_FAR_PASS_BODY
}
void far_pass_base(const FarColumns& f, std::size_t n, const float* p, const float* s, float sign,
                   float* __restrict acc, float* __restrict near) {
  MTCS_FAR_PASS_BODY
}
#undef MTCS_FAR_PASS_BODY

}  // namespace

void VoidSurface::potential_row(const Vec3& x, double* row) const {
  const std::size_t n = panels();
  const FarColumns f{far_.cx.data(), far_.cy.data(), far_.cz.data(), far_.area.data(), far_.far2.data(),
                     far_.xx.data(), far_.yy.data(), far_.zz.data(), far_.xy.data(), far_.xz.data(),
                     far_.yz.data(), far_.trace.data()};
  thread_local std::vector<float> acc, near;
  acc.assign(n, 0.0f);
  near.resize(n);
  std::fill(row, row + n, 0.0);  // the near panels, in double
  for (const Image& g : images_) {
    const Vec3 p = g.mult.cwiseProduct(x) + g.offset;
    const Vec3 local = p - far_.origin;
    const float at[3] = {float(local.x()), float(local.y()), float(local.z())};
    const float mirror[3] = {float(g.mult.x() * g.mult.y()), float(g.mult.x() * g.mult.z()),
                             float(g.mult.y() * g.mult.z())};
    if (has_avx2_fma()) far_pass_avx2(f, n, at, mirror, float(g.sign), acc.data(), near.data());
    else far_pass_base(f, n, at, mirror, float(g.sign), acc.data(), near.data());
    for (std::size_t j = 0; j < n; ++j)
      if (near[j] != 0) row[j] += g.sign * near_potential(j, p);
  }
  const double inv4pi = 1 / (4 * std::numbers::pi);
  for (std::size_t j = 0; j < n; ++j) row[j] = inv4pi * (row[j] + double(acc[j]));
}

double VoidSurface::panel_gradient(std::size_t j, const Vec3& x, const Vec3& normal) const {
  const double R2 = radius_[j] * radius_[j];
  double sum = 0;
  for (const Image& g : images_) {
    const Vec3 p = g.mult.cwiseProduct(x) + g.offset;
    const Vec3 m = g.mult.cwiseProduct(normal);
    auto point = [&](const Vec3& c, double area) {
      const Vec3 r = p - c;
      const double inv = 1 / r.norm();
      return -area * m.dot(r) * inv * inv * inv;
    };
    double v = 0;
    if ((p - centroid_[j]).squaredNorm() < kPoints * kPoints * R2) {
      // Per sub-triangle: exactly within kNearSubGradient of its size, else as a point.
      for (std::size_t s = begin_[j]; s < begin_[j + 1]; ++s) {
        if ((p - sub_[s].centroid).squaredNorm() < kNearSubGradient * kNearSubGradient * 2 * sub_[s].area)
          v += m.dot(sub_[s].source.gradient(p));
        else
          v += point(sub_[s].centroid, sub_[s].area);
      }
    } else {
      v = point(centroid_[j], area_[j]);
    }
    sum += g.sign * v;
  }
  return sum;
}

bool VoidSurface::reaches(const Vec3& a, const Vec3& b, double radius) const {
  const Vec3 d = b - a;
  const double dd = d.squaredNorm();
  auto distance = [&](const Vec3& p) {
    const double t = dd > 0 ? std::clamp((p - a).dot(d) / dd, 0.0, 1.0) : 0.0;
    return (p - a - t * d).norm();
  };
  // Exactly, by the segment-triangle distance. A ball bound (sqrt(2 area) about a sub-triangle's
  // centroid) reached 5-8 mm beyond a 16 mm panel's wall, and a bore that near lost its
  // reflection: on the cup 3 random layouts in 12 ran 30-39 K RMS off T3
  // (experiments/thermal/coupled/README.md). Nor is that ball a bound on a sliver (the planes cut
  // some): a panel is screened by its farthest sub-triangle corner instead.
  for (std::size_t j = 0; j < panels(); ++j) {
    if (distance(centroid_[j]) >= radius + corner_reach_[j]) continue;
    for (std::size_t s = begin_[j]; s < begin_[j + 1]; ++s) {
      const TriangleSource& t = sub_[s].source;
      if (geometry::segment_triangle_distance(a, b, t.corner(0), t.corner(1), t.corner(2)) < radius) return true;
    }
  }
  return false;
}

Eigen::MatrixXd VoidSurface::potentials(std::span<const Vec3> targets) const {
  Eigen::MatrixXd S(Eigen::Index(targets.size()), Eigen::Index(panels()));
  fill_potentials(targets, S);
  return S;
}

void VoidSurface::fill_potentials(std::span<const Vec3> targets, Eigen::MatrixXd& S) const {
  const std::size_t n = panels(), t = targets.size();
  auto row = [&](std::size_t i) {
    thread_local std::vector<double> values;
    values.resize(n);
    potential_row(targets[i], values.data());
    for (std::size_t j = 0; j < n; ++j) S(Eigen::Index(i), Eigen::Index(j)) = values[j];
  };
  // Many targets (the samples, once per model) in parallel, each row its own; a bore's walls inline.
  if (t > 64) tbb::parallel_for(std::size_t(0), t, row);
  else for (std::size_t i = 0; i < t; ++i) row(i);
}

std::shared_ptr<const Eigen::MatrixXd> VoidSurface::kept_potentials(std::span<const Vec3> targets, Keep keep) const {
  io::CacheKey key = panel_matrix_key("void-potentials");
  add_panels(key);
  for (const Vec3& p : targets) key.add_values(std::span<const double>(p.data(), 3));
  return kept_panel_matrix(key, Eigen::Index(targets.size()), Eigen::Index(panels()), keep,
                           [&](Eigen::MatrixXd& s) { fill_potentials(targets, s); });
}

Eigen::MatrixXf VoidSurface::layer(const Eigen::MatrixXf& d) const {
  Eigen::MatrixXf tau = Eigen::MatrixXf::Zero(inverse_transposed_.cols(), d.cols());
  add_skinny_product(inverse_transposed_, d, tau);
  return tau;
}

Eigen::MatrixXd VoidSurface::response(std::span<const Vec3> targets) const { return times_inverse(potentials(targets)); }

Eigen::MatrixXd VoidSurface::times_inverse(const Eigen::MatrixXd& r) const {
  // (R A^-1)^T = A^-T R^T. No rows (a block with no convective face): Eigen's triangular solve
  // would bind a reference to the empty right-hand side's null data (UBSan).
  if (r.rows() == 0) return Eigen::MatrixXd(0, r.cols());
  const Eigen::MatrixXd y = lu_.transpose().solve(r.transpose());
  return y.transpose();
}

}  // namespace mtcs::thermal
