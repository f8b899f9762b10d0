#include "mtcs/thermal/line_sinks.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "line_sink_fields.h"
#include "line_sink_tables.h"
#include "segment_potential.h"

namespace mtcs::thermal {

using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The six faces of a box as rectangles (two triangles each), in BlockFace order.
std::array<std::array<Vec3, 4>, 6> face_corners(const Box& b) {
  const Vec3& lo = b.min;
  const Vec3& hi = b.max;
  std::array<std::array<Vec3, 4>, 6> out;
  for (int a = 0; a < 3; ++a) {
    const int u = (a + 1) % 3, v = (a + 2) % 3;
    for (int side = 0; side < 2; ++side) {
      Vec3 c = lo;
      c[a] = side ? hi[a] : lo[a];
      std::array<Vec3, 4> r{c, c, c, c};
      r[1][u] = hi[u];
      r[2][u] = hi[u];
      r[2][v] = hi[v];
      r[3][v] = hi[v];
      out[2 * a + side] = r;
    }
  }
  return out;
}

bool on_plane(const Vec3& p, int axis, double value, double tol) {
  return std::abs(p[axis] - value) <= tol;
}

// Point in a triangle lying in the plane of a face (2-D test on the face's other axes).
bool in_triangle(const Vec3& p, const HeatedTriangle& t, int axis) {
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  auto cross = [&](const Vec3& a, const Vec3& b, const Vec3& q) {
    return (b[u] - a[u]) * (q[v] - a[v]) - (b[v] - a[v]) * (q[u] - a[u]);
  };
  const double c0 = cross(t.a, t.b, p), c1 = cross(t.b, t.c, p), c2 = cross(t.c, t.a, p);
  return (c0 >= 0 && c1 >= 0 && c2 >= 0) || (c0 <= 0 && c1 <= 0 && c2 <= 0);
}

// The part of a channel's axis inside the block (Liang-Barsky); ends already inside are kept
// bit for bit, so the cache keys of ordinary channels do not change. Empty: nothing inside.
std::optional<geometry::Segment> clip_to_block(const Box& box, const geometry::Segment& s) {
  const Vec3 d = s.p1 - s.p0;
  double t0 = 0, t1 = 1;
  for (int a = 0; a < 3; ++a) {
    if (d[a] == 0) {
      if (s.p0[a] < box.min[a] || s.p0[a] > box.max[a]) return std::nullopt;
      continue;
    }
    double ta = (box.min[a] - s.p0[a]) / d[a], tb = (box.max[a] - s.p0[a]) / d[a];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  if (!(t0 < t1)) return std::nullopt;
  return geometry::Segment{t0 > 0 ? Vec3(s.p0 + t0 * d) : s.p0, t1 < 1 ? Vec3(s.p0 + t1 * d) : s.p1};
}

}  // namespace

// ---- cache blocks ----------------------------------------------------------------------------

struct LineSinkCache::ChannelBlock {
  ChannelAxis axis;
  PointSet walls;  // 4 wall points per element, all images, relative to walls_origin
  Vec3 walls_origin = Vec3::Zero();
  bool walls_single = false;  // the radius is coarse enough for the float kernel
  int cols = 0;
  std::vector<float> sample_cols_f;   // samples x cols, column-major (single precision)
  std::vector<double> sample_cols_d;  // the same in double precision
  MatrixXd face_means;                // convective faces x cols
  MatrixXd self;                      // rows x cols: own columns at own rows (V_self removed)
  std::vector<double> self_dipole;    // per row: the own element's dipole at its own wall
  VectorXd heat_rows;                 // heat input's field at the rows
  MatrixXd face_rows;                 // rows x convective faces
  MatrixXd far_rows;                  // rows x 4: the far lattice's kernel (see Impl::far_kernel)
  MatrixXd moments;                   // 4 x cols: each column's charge and first moment
};

struct LineSinkCache::PairBlock {
  MatrixXd block;  // rows of the first channel x columns of the second
};

void LineSinkCache::clear() {
  channels_.clear();
  pairs_.clear();
}

// ---- the model -------------------------------------------------------------------------------

struct ConvectiveFace {
  int face = 0;
  double film = 0, ambient = 0;
  double area = 0, convective_area = 0;
  std::array<Vec3, 4> corners;
  std::vector<Vec3> cool;           // the grid points off the heated triangles
  Vec3 center;
};

struct LineSinkModel::Impl {
  Setting setting;
  LineSinkOptions options;
  int kinds = 1;  // columns per element: 1 (sink) or 3 (sink, two dipoles)
  double inv4pik = 0;
  double tol = 0;
  std::vector<Image> images;      // summed exactly
  std::vector<Image> far_images;  // summed as the charge and dipole of the whole block's image
  Vec3 center = Vec3::Zero();     // the block's centre: where the moments are taken
  Vec3 sample_origin = Vec3::Zero();  // the samples' centre: their float coordinates' origin
  Eigen::Vector4d heat_moments = Eigen::Vector4d::Zero();
  std::vector<Eigen::Vector4d> face_moments;
  MatrixXd far_samples;       // samples x 4: the far lattice for the channels' columns
  MatrixXd far_samples_fixed; // the same for the heat input and the faces (exact to `images`)
  MatrixXd far_face_means;                   // faces x 4: the far lattice for the channels
  MatrixXd far_face_means_fixed;             // the same for the heat input and the faces
  FieldGrid face_grid;
  // The heat input's field on a `heat_grid` mm grid, for collocation points off `heat_near` (the heated
  // triangles' bounds grown by two cells); nearer, it is summed exactly.
  FieldGrid heat_grid;
  Box heat_near = Box::empty();

  // The far lattice's kernel on the same grid: its images of the centre lie a block's width or
  // more outside, so it is smooth everywhere inside.
  FieldGrid far_grid;
  Eigen::Vector4d far_at(const Vec3& p) const {
    if (far_grid.values.empty() || !setting.block.contains(p)) return far_kernel(p);
    Eigen::Vector4d v;
    far_grid.interpolate(p, v.data());
    return v;
  }

  double heat_at(const Vec3& p) const {
    if (heat_grid.values.empty() || heat_near.contains(p) || !setting.block.contains(p)) return heat_field(p);
    double v;
    heat_grid.interpolate(p, &v);
    return v;
  }
  std::vector<ConvectiveFace> faces;
  std::optional<double> fixed_constant;  // an isothermal face's ambient
  double heat_in = 0;
  std::size_t n_samples = 0;
  PointSet sample_set;                       // the samples, image-expanded
  PointSet face_set;                         // the convective faces' grid points, one target each
  MatrixXd face_average;                     // faces x grid points: each face's mean
  VectorXd heat_samples;                     // heat input's field at the samples
  MatrixXd face_samples;                     // samples x faces: unit face loss
  VectorXd heat_face_means;                  // per face: heat input's field, face mean
  MatrixXd face_face_means;                  // faces x faces

  double heat_field(const Vec3& p) const {
    double sum = 0;
    for (const HeatedTriangle& t : setting.heat_in)
      sum += t.flux * triangle_image_potential(images, t.a, t.b, t.c, p);
    return sum * inv4pik;
  }
  // Field of a unit uniform loss (W/mm^2 out of the steel) over a face.
  double face_field(const ConvectiveFace& f, const Vec3& p) const {
    const auto& c = f.corners;
    return -inv4pik * (triangle_image_potential(images, c[0], c[1], c[2], p) +
                       triangle_image_potential(images, c[0], c[2], c[3], p));
  }


  // Adds w * (columns of `axis` at p) to col[0 .. elements * kinds).
  void add_columns(const ChannelAxis& axis, const Vec3& p, double w, double* col) const {
    double phi[64], d1[64], d2[64];
    const int m = axis.elements;
    element_fields(axis, p, phi, kinds == 3 ? d1 : nullptr, d2);
    const double s = w * inv4pik;
    for (int e = 0; e < m; ++e) {
      col[e * kinds] -= s * phi[e];  // a sink: q' W/mm leaves the steel
      if (kinds == 3) {
        col[e * kinds + 1] += s * d1[e];
        col[e * kinds + 2] += s * d2[e];
      }
    }
  }

  // The far images of the block, each seen as a point charge and dipole at its centre:
  // (sum sigma / d, sum sigma L_g (s - g(c)) / d^3) / (4 pi k), d = |s - g(c)|. Dotted with the
  // charge and first moment (about c) of everything in the block, it is the far lattice's field.
  Eigen::Vector4d far_kernel(const Vec3& s) const { return far_kernel(s, far_images); }
  Eigen::Vector4d far_kernel(const Vec3& s, std::span<const Image> far) const {
    Eigen::Vector4d k = Eigen::Vector4d::Zero();
    for (const Image& g : far) {
      const Vec3 d = s - (g.mult.cwiseProduct(center) + g.offset);
      const double r2 = d.squaredNorm();
      const double inv = 1 / std::sqrt(r2);
      k[0] += g.sign * inv;
      k.tail<3>() += (g.sign * inv / r2) * g.mult.cwiseProduct(d);
    }
    return k * inv4pik;
  }

  // The wall points of element e: m +- R n1, m +- R n2.
  std::array<Vec3, 4> wall_points(const ChannelAxis& a, int e) const {
    const Vec3 m = a.p0 + ((e + 0.5) * a.element_length) * a.u;
    return {m + a.radius * a.n1, m - a.radius * a.n1, m + a.radius * a.n2, m - a.radius * a.n2};
  }

  // The rows' functionals of any field f (images included by f): per element the wall's
  // four-point mean and, for T2d, the half-differences along n1 and n2 (first harmonic).
  template <class Field>
  void row_functionals(const ChannelAxis& rows, Field&& f, int width, double* out, int stride) const {
    std::vector<double> v(4 * width);
    for (int e = 0; e < rows.elements; ++e) {
      const auto w = wall_points(rows, e);
      for (int i = 0; i < 4; ++i) f(w[i], v.data() + std::size_t(i) * std::size_t(width));
      for (int c = 0; c < width; ++c) {
        const double* x = &v[c];
        out[(e * kinds) + c * stride] = 0.25 * (x[0] + x[width] + x[2 * width] + x[3 * width]);
        if (kinds == 3) {
          out[(e * kinds + 1) + c * stride] = 0.5 * (x[0] - x[width]);
          out[(e * kinds + 2) + c * stride] = 0.5 * (x[2 * width] - x[3 * width]);
        }
      }
    }
  }

  // Columns of `source` at every target of a point set: targets x cols. In single precision
  // only where asked (samples, face grids): a wall point sits a radius, maybe 1e-3 mm, from
  // its axis, finer than a float resolves at the block's coordinates.
  MatrixXd columns_at(const ChannelAxis& source, const PointSet& ps, bool single,
                      const Vec3& origin) const {
    const int cols = source.elements * kinds;
    MatrixXd out = MatrixXd::Zero(ps.targets(), cols);
    if (single && ps.slots > 0) {
      const std::size_t T = ps.targets();
      std::vector<float> acc(T * cols, 0.0f);
      element_fields_float_slots(source, origin, kinds, ps.sx.data(), ps.sy.data(), ps.sz.data(), ps.sw.data(), T,
                                 ps.slots, acc.data());
      for (int c = 0; c < cols; ++c) {
        const float scale = float((c % kinds == 0 ? -1 : 1) * inv4pik);
        for (std::size_t t = 0; t < T; ++t) out(t, c) = scale * acc[c * T + t];
      }
    } else if (single) {
      const std::size_t n = ps.points.size();
      std::vector<float> buf(n * cols);
      element_fields_float(source, origin, kinds, ps.x.data(), ps.y.data(), ps.z.data(), n, buf.data());
      for (int c = 0; c < cols; ++c) {
        const double scale = (c % kinds == 0 ? -1 : 1) * inv4pik;  // a sink takes heat out
        const float* v = buf.data() + std::size_t(c) * n;  // n may be 0
        for (std::size_t t = 0; t < ps.targets(); ++t) {
          double acc = 0;
          for (std::size_t i = ps.begin[t]; i < ps.begin[t + 1]; ++i) acc += ps.points[i].weight * v[i];
          out(t, c) = scale * acc;
        }
      }
    } else {
      std::vector<double> col(cols);
      for (std::size_t t = 0; t < ps.targets(); ++t) {
        std::fill(col.begin(), col.end(), 0.0);
        for (std::size_t i = ps.begin[t]; i < ps.begin[t + 1]; ++i)
          add_columns(source, ps.points[i].point, ps.points[i].weight, col.data());
        for (int c = 0; c < cols; ++c) out(t, c) = col[c];
      }
    }
    return out;
  }

  // Columns of `source` at the rows of a channel: its wall points' mean and half-differences.
  MatrixXd channel_at_rows(const LineSinkCache::ChannelBlock& rows, const ChannelAxis& source) const {
    const MatrixXd v = columns_at(source, rows.walls, rows.walls_single, rows.walls_origin);
    MatrixXd out(rows.axis.elements * kinds, v.cols());
    for (int e = 0; e < rows.axis.elements; ++e) {
      out.row(e * kinds) = 0.25 * (v.row(4 * e) + v.row(4 * e + 1) + v.row(4 * e + 2) + v.row(4 * e + 3));
      if (kinds == 3) {
        out.row(e * kinds + 1) = 0.5 * (v.row(4 * e) - v.row(4 * e + 1));
        out.row(e * kinds + 2) = 0.5 * (v.row(4 * e + 2) - v.row(4 * e + 3));
      }
    }
    return out;
  }

  std::shared_ptr<LineSinkCache::ChannelBlock> build_channel(const Channel& ch) const {
    auto b = std::make_shared<LineSinkCache::ChannelBlock>();
    b->axis = channel_axis(ch, options.elements);
    const ChannelAxis& a = b->axis;
    const int cols = a.elements * kinds;
    b->cols = cols;
    // Wall points relative to the channel's middle: a float resolves 6e-8 of the distances
    // there, fine next to a radius above 1e-3 of the block and the channel.
    b->walls_origin = a.p0 + 0.5 * a.length * a.u;
    b->walls_single = options.single_precision &&
                      a.radius >= 1e-3 * (setting.block.size().norm() + a.length);
    for (int e = 0; e < a.elements; ++e)
      for (const Vec3& p : wall_points(a, e)) {
        b->walls.add(images, p, tol, 1.0, b->walls_origin);
        b->walls.close_target();
      }
    if (b->walls_single) b->walls.make_slots();
    // At the samples.
    const MatrixXd at_samples = columns_at(a, sample_set, options.single_precision, sample_origin);
    if (options.single_precision) {
      b->sample_cols_f.resize(n_samples * cols);
      for (int c = 0; c < cols; ++c)
        for (std::size_t s = 0; s < n_samples; ++s) b->sample_cols_f[c * n_samples + s] = float(at_samples(s, c));
    } else {
      b->sample_cols_d.assign(at_samples.data(), at_samples.data() + at_samples.size());
    }
    // At the convective faces' grids (means).
    b->face_means = face_average * columns_at(a, face_set, options.single_precision, center);
    // Own rows: the own columns, the heat input and the face losses.
    b->self = channel_at_rows(*b, a);
    b->self_dipole.assign(cols, 0.0);
    if (kinds == 3)
      for (int e = 0; e < a.elements; ++e)
        for (int j = 1; j <= 2; ++j) {
          const int r = e * 3 + j;
          b->self_dipole[r] = b->self(r, r);
          b->self(r, r) = 0;  // V_self: kept apart, the film condition weighs it differently
        }
    b->heat_rows.resize(cols);
    row_functionals(a, [&](const Vec3& p, double* v) { v[0] = heat_at(p); }, 1,
                    b->heat_rows.data(), cols);
    b->far_rows.resize(cols, 4);
    row_functionals(a, [&](const Vec3& p, double* v) {
      const Eigen::Vector4d k = far_at(p);
      for (int i = 0; i < 4; ++i) v[i] = k[i];
    }, 4, b->far_rows.data(), cols);
    b->moments = MatrixXd::Zero(4, cols);
    for (int e = 0; e < a.elements; ++e) {
      const Vec3 mid = a.p0 + ((e + 0.5) * a.element_length) * a.u;
      const double L = a.element_length;
      b->moments(0, e * kinds) = -L;  // a sink: charge -L per unit strength
      b->moments.block<3, 1>(1, e * kinds) = -L * (mid - center);
      if (kinds == 3) {
        b->moments.block<3, 1>(1, e * kinds + 1) = L * a.n1;
        b->moments.block<3, 1>(1, e * kinds + 2) = L * a.n2;
      }
    }
    b->face_rows.resize(cols, faces.size());
    if (!faces.empty())
      row_functionals(a, [&](const Vec3& p, double* v) {
        if (setting.block.contains(p)) return face_grid.interpolate(p, v);
        for (std::size_t f = 0; f < faces.size(); ++f) v[f] = face_field(faces[f], p);  // no extrapolation
      },
                      int(faces.size()), b->face_rows.data(), cols);
    return b;
  }
};

LineSinkModel::LineSinkModel(const Setting& setting, const Samples& samples, LineSinkOptions options)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  if (options.elements < 1 || options.elements > 64)
    throw std::invalid_argument("line sinks: elements per channel must be in 1..64");
  if (options.images < 0) throw std::invalid_argument("line sinks: images must be >= 0");
  if (!(setting.conductivity > 0)) throw std::invalid_argument("line sinks: conductivity must be > 0");
  m.setting = setting;
  m.options = options;
  m.kinds = options.tier == Tier::T2d ? 3 : 1;
  m.inv4pik = 1 / (4 * std::numbers::pi * setting.conductivity);
  const Box& box = setting.block;
  m.tol = 1e-12 * (box.max.cwiseAbs().maxCoeff() + box.min.cwiseAbs().maxCoeff() + box.size().maxCoeff());

  std::array<double, 6> sign{};
  for (int f = 0; f < 6; ++f) {
    const FaceCondition& fc = setting.faces[f];
    sign[f] = fc.film == kInf ? -1 : 1;
    if (fc.film == kInf) {
      if (m.fixed_constant && *m.fixed_constant != fc.ambient)
        throw std::invalid_argument("line sinks: isothermal faces must share one ambient");
      m.fixed_constant = fc.ambient;
    }
  }
  m.images = block_images(box, sign, options.images);
  if (options.far_images > options.images) {
    m.far_images = block_images(box, sign, options.far_images);
    m.far_images.erase(m.far_images.begin(), m.far_images.begin() + m.images.size());
  }
  m.center = 0.5 * (box.min + box.max);
  // At the samples (the bulk of the work) fewer images may be summed exactly, the rest as the
  // far lattice's charge and dipole.
  const int sample_levels = options.sample_images < 0 ? options.images : std::min(options.sample_images, options.images);
  const std::vector<Image> sample_images = block_images(box, sign, sample_levels);
  std::vector<Image> sample_far;
  if (options.far_images > sample_levels) {
    sample_far = block_images(box, sign, options.far_images);
    sample_far.erase(sample_far.begin(), sample_far.begin() + sample_images.size());
  }

  for (const HeatedTriangle& t : setting.heat_in) {
    const double q = t.flux * 0.5 * (t.b - t.a).cross(t.c - t.a).norm();
    m.heat_in += q;
    m.heat_moments[0] += q;
    m.heat_moments.tail<3>() += q * ((t.a + t.b + t.c) / 3 - m.center);
  }

  // Convective faces: one unknown uniform loss each, collocated on a grid of the face's part
  // that is not heated.
  const auto corners = face_corners(box);
  const int g = std::max(1, options.face_grid);
  for (int f = 0; f < 6; ++f) {
    const FaceCondition& fc = setting.faces[f];
    if (!(fc.film > 0) || fc.film == kInf) continue;
    ConvectiveFace cf;
    cf.face = f;
    cf.film = fc.film;
    cf.ambient = fc.ambient;
    cf.corners = corners[f];
    const int axis = f / 2;
    const double plane = (f % 2) ? box.max[axis] : box.min[axis];
    cf.area = (corners[f][1] - corners[f][0]).norm() * (corners[f][3] - corners[f][0]).norm();
    cf.convective_area = cf.area;
    std::vector<const HeatedTriangle*> on_face;
    for (const HeatedTriangle& t : setting.heat_in)
      if (on_plane(t.a, axis, plane, m.tol) && on_plane(t.b, axis, plane, m.tol) && on_plane(t.c, axis, plane, m.tol)) {
        on_face.push_back(&t);
        cf.convective_area -= 0.5 * (t.b - t.a).cross(t.c - t.a).norm();
      }
    if (cf.convective_area <= 1e-9 * cf.area) continue;
    std::vector<Vec3> grid, cool;
    for (int i = 0; i < g; ++i)
      for (int j = 0; j < g; ++j) {
        const Vec3 p = corners[f][0] + ((i + 0.5) / g) * (corners[f][1] - corners[f][0]) +
                       ((j + 0.5) / g) * (corners[f][3] - corners[f][0]);
        grid.push_back(p);
        bool heated = false;
        for (const HeatedTriangle* t : on_face) heated = heated || in_triangle(p, *t, axis);
        if (!heated) cool.push_back(p);
      }
    if (cool.empty()) cool = grid;
    cf.cool = cool;
    cf.center = 0.5 * (corners[f][0] + corners[f][2]);
    for (const Vec3& p : cool) {
      m.face_set.add(sample_images, p, m.tol, 1.0, m.center);
      m.face_set.close_target();
    }
    m.faces.push_back(std::move(cf));
  }

  // The samples: expanded by the images, and the layout-independent fields there.
  m.n_samples = samples.size();
  // Float coordinates from the samples' own centre: a float resolves 6e-8 of their spread,
  // not of the block's size or distance from the origin.
  if (m.n_samples) {
    Box bounds = Box::empty();
    for (const Vec3& p : samples.points) bounds.min = bounds.min.cwiseMin(p), bounds.max = bounds.max.cwiseMax(p);
    m.sample_origin = 0.5 * (bounds.min + bounds.max);
  }
  for (const Vec3& p : samples.points) {
    m.sample_set.add(sample_images, p, m.tol, 1.0, m.sample_origin);
    m.sample_set.close_target();
  }
  if (m.n_samples) m.sample_set.make_slots();
  if (!m.faces.empty()) m.face_set.make_slots();
  m.face_average = MatrixXd::Zero(m.faces.size(), m.face_set.targets());
  for (std::size_t f = 0, point = 0; f < m.faces.size(); ++f)
    for (std::size_t i = 0; i < m.faces[f].cool.size(); ++i) m.face_average(f, point++) = 1.0 / double(m.faces[f].cool.size());
  const std::size_t nf = m.faces.size();
  for (const ConvectiveFace& cf : m.faces) {
    Eigen::Vector4d mo;
    mo << -cf.area, -cf.area * (cf.center - m.center);
    m.face_moments.push_back(mo);
  }
  m.far_samples.resize(m.n_samples, 4);
  m.far_samples_fixed.resize(m.n_samples, 4);
  for (std::size_t s = 0; s < m.n_samples; ++s) {
    m.far_samples.row(s) = m.far_kernel(samples.points[s], sample_far).transpose();
    m.far_samples_fixed.row(s) = m.far_kernel(samples.points[s]).transpose();
  }
  m.far_face_means = MatrixXd::Zero(nf, 4);
  m.far_face_means_fixed = MatrixXd::Zero(nf, 4);
  for (std::size_t f = 0; f < nf; ++f) {
    for (const Vec3& p : m.faces[f].cool) {
      m.far_face_means.row(f) += m.far_kernel(p, sample_far).transpose();
      m.far_face_means_fixed.row(f) += m.far_kernel(p).transpose();
    }
    m.far_face_means.row(f) /= double(m.faces[f].cool.size());
    m.far_face_means_fixed.row(f) /= double(m.faces[f].cool.size());
  }
  if (nf) {
    FieldGrid& g = m.face_grid;
    constexpr int cells = 10;
    g.origin = box.min;
    g.step = box.size() / cells;
    g.nodes = {cells + 1, cells + 1, cells + 1};
    g.fields = int(nf);
    g.values.resize(std::size_t(cells + 1) * (cells + 1) * (cells + 1) * nf);
    std::size_t n = 0;
    for (int k = 0; k <= cells; ++k)
      for (int j = 0; j <= cells; ++j)
        for (int i = 0; i <= cells; ++i) {
          const Vec3 p = box.min + g.step.cwiseProduct(Vec3(i, j, k));
          for (std::size_t f = 0; f < nf; ++f) g.values[n++] = m.face_field(m.faces[f], p);
        }
  }
  // Tabulated fields pay off only at their spacing: a block too large for 64 cells of
  // `heat_grid` mm per axis sums them exactly.
  const bool grids = options.heat_grid > 0 && (box.size() / options.heat_grid).maxCoeff() <= 64;
  auto grid_over_block = [&](FieldGrid& g, int fields) {
    g.origin = box.min;
    g.fields = fields;
    for (int a = 0; a < 3; ++a) {
      const int cells = std::clamp(int(std::ceil(box.size()[a] / options.heat_grid)), 3, 64);
      g.nodes[a] = cells + 1;
      g.step[a] = box.size()[a] / cells;
    }
    g.values.resize(std::size_t(g.nodes[0]) * g.nodes[1] * g.nodes[2] * fields);
  };
  if (!m.far_images.empty() && grids) {
    FieldGrid& g = m.far_grid;
    grid_over_block(g, 4);
    std::size_t n = 0;
    for (int k = 0; k < g.nodes[2]; ++k)
      for (int j = 0; j < g.nodes[1]; ++j)
        for (int i = 0; i < g.nodes[0]; ++i) {
          const Eigen::Vector4d v = m.far_kernel(box.min + g.step.cwiseProduct(Vec3(i, j, k)));
          for (int c = 0; c < 4; ++c) g.values[n++] = v[c];
        }
  }
  if (!setting.heat_in.empty() && grids) {
    FieldGrid& g = m.heat_grid;
    grid_over_block(g, 1);
    std::size_t n = 0;
    for (int k = 0; k < g.nodes[2]; ++k)
      for (int j = 0; j < g.nodes[1]; ++j)
        for (int i = 0; i < g.nodes[0]; ++i) g.values[n++] = m.heat_field(box.min + g.step.cwiseProduct(Vec3(i, j, k)));
    for (const HeatedTriangle& t : setting.heat_in)
      for (const Vec3& v : {t.a, t.b, t.c}) {
        m.heat_near.min = m.heat_near.min.cwiseMin(v);
        m.heat_near.max = m.heat_near.max.cwiseMax(v);
      }
    const Vec3 margin = Vec3::Constant(2 * g.step.maxCoeff());
    m.heat_near.min -= margin;
    m.heat_near.max += margin;
  }
  m.heat_samples.resize(m.n_samples);
  m.face_samples.resize(m.n_samples, nf);
  for (std::size_t s = 0; s < m.n_samples; ++s) {
    m.heat_samples[s] = m.heat_field(samples.points[s]);
    for (std::size_t f = 0; f < nf; ++f) m.face_samples(s, f) = m.face_field(m.faces[f], samples.points[s]);
  }
  m.heat_face_means.resize(nf);
  m.face_face_means.resize(nf, nf);
  for (std::size_t f = 0; f < nf; ++f) {
    const std::vector<Vec3>& plain = m.faces[f].cool;
    double h = 0;
    for (const Vec3& p : plain) h += m.heat_field(p);
    m.heat_face_means[f] = h / double(plain.size());
    for (std::size_t f2 = 0; f2 < nf; ++f2) {
      double s = 0;
      for (const Vec3& p : plain) s += m.face_field(m.faces[f2], p);
      m.face_face_means(f, f2) = s / double(plain.size());
    }
  }
}

LineSinkModel::~LineSinkModel() = default;
LineSinkModel::LineSinkModel(LineSinkModel&&) noexcept = default;
const LineSinkOptions& LineSinkModel::options() const { return impl_->options; }

LineSinkSolution LineSinkModel::solve(std::span<const Channel> channels, LineSinkCache& cache) const {
  const Impl& m = *impl_;
  if (cache.owner_ != impl_.get()) {
    cache.clear();
    cache.owner_ = impl_.get();
  }
  const std::size_t nc = channels.size();
  if (nc == 0 && !m.fixed_constant)
    throw std::invalid_argument("line sinks: no channel and no isothermal face: no steady state");
  // Only the steel conducts: a channel's part outside the block (a connection in the air) takes
  // no heat, and its images would land inside.
  std::vector<Channel> inside(channels.begin(), channels.end());
  for (Channel& ch : inside) {
    const auto clipped = clip_to_block(m.setting.block, ch.axis);
    if (!clipped) throw std::invalid_argument("line sinks: a channel lies outside the block");
    ch.axis = *clipped;
  }
  channels = inside;
  // Look up or build every channel's and pair's blocks.
  using Key = LineSinkCache::Key;
  std::vector<Key> keys(nc);
  std::vector<std::shared_ptr<LineSinkCache::ChannelBlock>> blocks(nc);
  std::map<Key, std::shared_ptr<LineSinkCache::ChannelBlock>> used;
  for (std::size_t c = 0; c < nc; ++c) {
    const Channel& ch = channels[c];
    if (!((ch.axis.p1 - ch.axis.p0).norm() > 0) || !(ch.radius > 0))
      throw std::invalid_argument("line sinks: a channel needs a positive length and radius");
    keys[c] = {ch.axis.p0.x(), ch.axis.p0.y(), ch.axis.p0.z(), ch.axis.p1.x(), ch.axis.p1.y(),
               ch.axis.p1.z(), ch.radius};
    auto it = cache.channels_.find(keys[c]);
    if (it != cache.channels_.end()) {
      blocks[c] = it->second;
      ++cache.channels_reused;
    } else {
      blocks[c] = m.build_channel(ch);
      ++cache.channels_computed;
    }
    used[keys[c]] = blocks[c];
  }
  std::map<std::pair<Key, Key>, std::shared_ptr<LineSinkCache::PairBlock>> used_pairs;
  auto pair = [&](std::size_t r, std::size_t c) -> const MatrixXd& {
    const auto k = std::make_pair(keys[r], keys[c]);
    auto found = used_pairs.find(k);
    if (found != used_pairs.end()) return found->second->block;
    auto it = cache.pairs_.find(k);
    std::shared_ptr<LineSinkCache::PairBlock> p;
    if (it != cache.pairs_.end()) {
      p = it->second;
    } else {
      p = std::make_shared<LineSinkCache::PairBlock>();
      p->block = m.channel_at_rows(*blocks[r], blocks[c]->axis);
    }
    used_pairs[k] = p;
    return p->block;
  };

  // Unknowns: the channels' columns, the faces' losses, the free constant.
  std::vector<int> offset(nc + 1, 0);
  for (std::size_t c = 0; c < nc; ++c) offset[c + 1] = offset[c] + blocks[c]->cols;
  const int n_ch = offset[nc];
  const int nf = int(m.faces.size());
  const bool free_constant = !m.fixed_constant;
  const int n = n_ch + nf + (free_constant ? 1 : 0);
  const int t0 = n_ch + nf;  // column of the free constant
  const double fixed = m.fixed_constant.value_or(0.0);
  const double k = m.setting.conductivity;
  MatrixXd A = MatrixXd::Zero(n, n);
  VectorXd rhs = VectorXd::Zero(n);

  for (std::size_t c = 0; c < nc; ++c) {
    const auto& b = *blocks[c];
    const Channel& ch = channels[c];
    const double R = b.axis.radius, h = ch.film;
    const double w1 = h == kInf ? 1 : h * R / (k + h * R);
    const double w2 = h == kInf ? 0 : 1 / (2 * std::numbers::pi * (k + h * R));
    const double beta = h == kInf ? -1 : (k - h * R) / (k + h * R);
    for (int r = 0; r < b.cols; ++r) {
      const int row = offset[c] + r;
      const bool mean_row = r % m.kinds == 0;
      const double wr = mean_row ? w1 : -beta;  // weight of the field's functional in this row
      const Eigen::RowVector4d far = b.far_rows.row(r);
      for (std::size_t d = 0; d < nc; ++d) {
        const MatrixXd& blk = d == c ? b.self : pair(c, d);
        A.block(row, offset[d], 1, blk.cols()) = wr * (blk.row(r) + far * blocks[d]->moments);
      }
      for (int f = 0; f < nf; ++f) A(row, n_ch + f) = wr * (b.face_rows(r, f) + far.dot(m.face_moments[f]));
      const double heat_r = b.heat_rows[r] + far.dot(m.heat_moments);
      if (mean_row) {
        A(row, row) -= w2;  // the film's drop: q' / (2 pi R h)
        if (free_constant) A(row, t0) = w1;
        rhs[row] = w1 * (ch.coolant - heat_r - fixed);
      } else {
        A(row, row) += b.self_dipole[r];
        rhs[row] = beta * heat_r;
      }
    }
  }
  for (int f = 0; f < nf; ++f) {
    const ConvectiveFace& cf = m.faces[f];
    const int row = n_ch + f;
    // loss / (h A_conv) - face mean temperature = - ambient
    const Eigen::RowVector4d far_ch = m.far_face_means.row(f), far = m.far_face_means_fixed.row(f);
    for (std::size_t c = 0; c < nc; ++c)
      A.block(row, offset[c], 1, blocks[c]->cols) = -(blocks[c]->face_means.row(f) + far_ch * blocks[c]->moments);
    for (int f2 = 0; f2 < nf; ++f2) A(row, n_ch + f2) = -(m.face_face_means(f, f2) + far.dot(m.face_moments[f2]));
    A(row, row) += cf.area / (cf.film * cf.convective_area);
    if (free_constant) A(row, t0) = -1;
    rhs[row] = m.heat_face_means[f] + far.dot(m.heat_moments) + fixed - cf.ambient;
  }
  if (free_constant) {  // the energy balance fixes the constant
    for (std::size_t c = 0; c < nc; ++c) {
      const auto& b = *blocks[c];
      for (int e = 0; e < b.axis.elements; ++e) A(t0, offset[c] + e * m.kinds) = b.axis.element_length;
    }
    for (int f = 0; f < nf; ++f) A(t0, n_ch + f) = m.faces[f].area;
    rhs[t0] = m.heat_in;
  }

  VectorXd x;
  if (m.options.tier == Tier::T1) {
    // One strength for every element: the columns summed, the mean rows summed by length.
    const int n1 = 1 + nf + (free_constant ? 1 : 0);
    MatrixXd P = MatrixXd::Zero(n, n1), Rm = MatrixXd::Zero(n1, n);
    for (std::size_t c = 0; c < nc; ++c)
      for (int e = 0; e < blocks[c]->axis.elements; ++e) {
        P(offset[c] + e, 0) = 1;
        Rm(0, offset[c] + e) = blocks[c]->axis.element_length;
      }
    for (int i = n_ch; i < n; ++i) {
      P(i, 1 + i - n_ch) = 1;
      Rm(1 + i - n_ch, i) = 1;
    }
    const VectorXd y = (Rm * A * P).partialPivLu().solve(Rm * rhs);
    x = P * y;
  } else {
    x = A.partialPivLu().solve(rhs);
  }

  LineSinkSolution out;
  out.heat_in = m.heat_in;
  const double T0 = free_constant ? x[t0] : fixed;
  VectorXd T = m.heat_samples + VectorXd::Constant(m.n_samples, T0);
  if (nf) T += m.face_samples * x.segment(n_ch, nf);
  // The far lattice: the moments of everything in the block.
  Eigen::Vector4d fixed_moments = m.heat_moments, channel_moments = Eigen::Vector4d::Zero();
  for (int f = 0; f < nf; ++f) fixed_moments += x[n_ch + f] * m.face_moments[f];
  for (std::size_t c = 0; c < nc; ++c) channel_moments += blocks[c]->moments * x.segment(offset[c], blocks[c]->cols);
  T += m.far_samples_fixed * fixed_moments + m.far_samples * channel_moments;
  const std::size_t ns = m.n_samples;
  for (std::size_t c = 0; c < nc; ++c) {
    const auto& b = *blocks[c];
    for (int col = 0; col < b.cols; ++col) {
      const double xi = x[offset[c] + col];
      if (m.options.single_precision) {
        const float* v = &b.sample_cols_f[col * ns];
        for (std::size_t s = 0; s < ns; ++s) T[s] += xi * double(v[s]);
      } else {
        const double* v = &b.sample_cols_d[col * ns];
        for (std::size_t s = 0; s < ns; ++s) T[s] += xi * v[s];
      }
    }
    double q = 0;
    for (int e = 0; e < b.axis.elements; ++e) q += x[offset[c] + e * m.kinds] * b.axis.element_length;
    out.channel_heat.push_back(q);
  }
  for (int f = 0; f < nf; ++f) out.face_heat += x[n_ch + f] * m.faces[f].area;
  out.temperature.assign(T.data(), T.data() + ns);

  cache.channels_ = std::move(used);
  cache.pairs_ = std::move(used_pairs);
  return out;
}

}  // namespace mtcs::thermal
