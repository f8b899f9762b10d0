// One channel's influence columns (what LineSinkCache keeps per channel): at the samples, at
// the convective faces' grids, at its own collocation rows, and its moments for the far lattice.

#include <algorithm>

#include "thermal/line_sinks/line_sink_model.h"
#include "thermal/linalg/skinny_product.h"

namespace mtcs::thermal {

std::vector<float> LineSinkModel::Impl::float_columns_at(const ChannelAxis& source, const PointSet& ps,
                                                         const Vec3& origin, double far_ratio) const {
  std::vector<float> acc;
  float_columns_into(source, ps, origin, far_ratio, acc);
  return acc;
}

void LineSinkModel::Impl::float_columns_into(const ChannelAxis& source, const PointSet& ps, const Vec3& origin,
                                             double far_ratio, std::vector<float>& acc) const {
  const int cols = source.elements * kinds;
  const std::size_t T = ps.targets();
  acc.assign(T * cols, 0.0f);
  const FarChunks far{ps.chunk_box.data(), ps.chunk, float(far_ratio)};
  const bool use_far = !ps.chunk_box.empty() && far_ratio > 0;
  element_fields_float_slots(source, origin, kinds, ps.sx.data(), ps.sy.data(), ps.sz.data(), ps.sw.data(), T,
                             ps.slots, acc.data(), use_far ? &far : nullptr);
  for (int c = 0; c < cols; ++c) {
    const float scale = float((c % kinds == 0 ? -1 : 1) * inv4pik);  // a sink takes heat out
    for (std::size_t t = 0; t < T; ++t) acc[c * T + t] *= scale;
  }
}

MatrixXd LineSinkModel::Impl::columns_at(const ChannelAxis& source, const PointSet& ps, bool single,
                                         const Vec3& origin, double far_ratio) const {
  const int cols = source.elements * kinds;
  if (single && ps.slots > 0) {
    const std::vector<float> v = float_columns_at(source, ps, origin, far_ratio);
    return Eigen::Map<const Eigen::MatrixXf>(v.data(), Eigen::Index(ps.targets()), cols).cast<double>();
  }
  MatrixXd out = MatrixXd::Zero(ps.targets(), cols);
  if (single) {
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

namespace {

// The rows' functionals from the columns at the wall points (4 per element, v(point, column)):
// the mean and the half-differences along n1 and n2.
template <class At>
MatrixXd rows_from(const ChannelAxis& rows, int kinds, Eigen::Index cols, At v) {
  MatrixXd out(rows.elements * kinds, cols);
  for (Eigen::Index c = 0; c < cols; ++c)
    for (int e = 0; e < rows.elements; ++e) {
      const double a = v(4 * e, c), b = v(4 * e + 1, c), p = v(4 * e + 2, c), q = v(4 * e + 3, c);
      out(e * kinds, c) = 0.25 * (a + b + p + q);
      if (kinds == 3) out(e * kinds + 1, c) = 0.5 * (a - b), out(e * kinds + 2, c) = 0.5 * (p - q);
    }
  return out;
}

}  // namespace

MatrixXd LineSinkModel::Impl::channel_at_rows(const LineSinkCache::ChannelBlock& rows, const ChannelAxis& source) const {
  // An element at least pair_far element lengths from a slot's wall points (all of them) takes
  // its multipole expansion there: q = h / d <= 1 / (2 pair_far), the walls' chunk boxes.
  const double ratio = options.pair_far > 0 ? 0.5 / options.pair_far : 0.0;
  if (!rows.walls_single || rows.walls.slots == 0) {
    const MatrixXd v = columns_at(source, rows.walls, rows.walls_single, rows.walls_origin, ratio);
    return rows_from(rows.axis, kinds, v.cols(), [&](int i, Eigen::Index c) { return v(i, c); });
  }
  // Straight from the float columns: no walls x columns matrix in double between them.
  thread_local std::vector<float> acc;
  float_columns_into(source, rows.walls, rows.walls_origin, ratio, acc);
  const std::size_t T = rows.walls.targets();
  return rows_from(rows.axis, kinds, source.elements * kinds,
                   [&](int i, Eigen::Index c) { return double(acc[std::size_t(c) * T + std::size_t(i)]); });
}

MatrixXd LineSinkModel::Impl::void_at_rows(const LineSinkCache::ChannelBlock& rows,
                                           const LineSinkCache::ChannelBlock& source) const {
  // Float, as the layer itself (void_surface.h): rows x cols from panels-long streams.
  Eigen::MatrixXf v = Eigen::MatrixXf::Zero(rows.void_rows.cols(), source.void_tau.cols());
  add_skinny_product(rows.void_rows, source.void_tau, v);
  return v.cast<double>();
}

MatrixXd LineSinkModel::Impl::channel_at_rows(const LineSinkCache::ChannelBlock& rows,
                                              const LineSinkCache::ChannelBlock& source) const {
  MatrixXd out = channel_at_rows(rows, source.axis);
  if (source.void_tau.size()) out += void_at_rows(rows, source);
  return out;
}

MatrixXd LineSinkModel::Impl::face_means_of(const ChannelAxis& source) const {
  if (!options.single_precision || face_set.slots == 0)
    return face_average * columns_at(source, face_set, options.single_precision, center, options.far_expansion);
  // Each face's grid points are consecutive targets: their means straight from the float
  // columns (no targets x columns matrix in double, no product with the mostly empty average).
  thread_local std::vector<float> acc;
  float_columns_into(source, face_set, center, options.far_expansion, acc);
  const std::size_t T = face_set.targets();
  const int cols = source.elements * kinds;
  MatrixXd out(Eigen::Index(faces.size()), cols);
  for (int c = 0; c < cols; ++c)
    for (std::size_t f = 0, t = 0; f < faces.size(); ++f) {
      const std::size_t n = faces[f].cool.size();
      double sum = 0;
      for (std::size_t i = 0; i < n; ++i, ++t) sum += double(acc[std::size_t(c) * T + t]);
      out(Eigen::Index(f), c) = sum / double(n);
    }
  return out;
}

Eigen::MatrixXf LineSinkModel::Impl::void_derivatives(const ChannelAxis& source) const {
  // A panel's two points are neighbouring targets, in one chunk: both take the closed forms or
  // both the expansion, whose error is smooth.
  thread_local std::vector<float> acc;
  float_columns_into(source, void_pairs, sample_origin, options.far_expansion, acc);
  const std::size_t T = void_pairs.targets(), n = T / 2;
  const int cols = source.elements * kinds;
  Eigen::MatrixXf d(Eigen::Index(n), cols);
  const float scale = float(1 / (2 * void_step));
  for (int c = 0; c < cols; ++c)
    for (std::size_t i = 0; i < n; ++i)
      d(Eigen::Index(i), c) = scale * (acc[std::size_t(c) * T + 2 * i] - acc[std::size_t(c) * T + 2 * i + 1]);
  return d;
}

Eigen::MatrixXf LineSinkModel::Impl::void_robin_rhs(const ChannelAxis& source, const MatrixXd& moments) const {
  thread_local std::vector<float> acc;
  float_columns_into(source, void_pairs, sample_origin, options.far_expansion, acc);
  const std::size_t T = void_pairs.targets(), n = T / 2;
  const int cols = source.elements * kinds;
  const VectorXd& H = void_surface->film_over_k();
  const MatrixXd far = far_panels * moments;  // panels x cols
  Eigen::MatrixXf rhs(Eigen::Index(n), cols);
  const double scale = 1 / (2 * void_step);
  const bool patch = void_surface->on_block_face();  // d = 0: the face's image keeps the flux
  for (int c = 0; c < cols; ++c)
    for (std::size_t i = 0; i < n; ++i) {
      const double plus = acc[std::size_t(c) * T + 2 * i], minus = acc[std::size_t(c) * T + 2 * i + 1];
      const auto r = Eigen::Index(i);
      const double derivative = patch ? 0.0 : scale * (plus - minus);
      rhs(r, c) = float(derivative - H[r] * (0.5 * (plus + minus) + far(r, c)));
    }
  return rhs;
}

std::shared_ptr<LineSinkCache::ChannelBlock> LineSinkModel::Impl::build_channel(const Channel& ch) const {
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
  // Sized once (4 M wall points x the images), so that the pushes below never regrow.
  const std::size_t expected = std::size_t(4 * a.elements) * images.size();
  b->walls.points.reserve(expected), b->walls.x.reserve(expected), b->walls.y.reserve(expected),
      b->walls.z.reserve(expected), b->walls.begin.reserve(4 * a.elements + 1);
  for (int e = 0; e < a.elements; ++e)
    for (const Vec3& p : wall_points(a, e)) {
      b->walls.add(images, p, tol, 1.0, b->walls_origin);
      b->walls.close_target();
    }
  // One chunk per slot: the slot's wall points (one image of the whole channel's walls) are
  // far from an element or not together, a function of the two channels' keys alone.
  if (b->walls_single) b->walls.make_slots(), b->walls.make_chunk_boxes(b->walls.targets());
  // At the samples.
  if (options.single_precision && sample_set.slots > 0) {
    b->sample_cols_f = float_columns_at(a, sample_set, sample_origin, options.far_expansion);
  } else if (options.single_precision) {
    const MatrixXd at_samples = columns_at(a, sample_set, true, sample_origin, options.far_expansion);
    b->sample_cols_f.resize(n_samples * cols);
    for (int c = 0; c < cols; ++c)
      for (std::size_t s = 0; s < n_samples; ++s) b->sample_cols_f[c * n_samples + s] = float(at_samples(s, c));
  } else {
    const MatrixXd at_samples = columns_at(a, sample_set, false, sample_origin, 0);
    b->sample_cols_d.assign(at_samples.data(), at_samples.data() + at_samples.size());
  }
  // At the convective faces' grids (means).
  b->face_means = face_means_of(a);
  // The part's void: the panels' potentials at the rows (any layer's field there is these times
  // the layer), and the columns' reflections (a bore reaching into the part keeps none).
  MatrixXd void_rows;
  if (void_surface) {
    std::vector<Vec3> walls;
    for (int e = 0; e < a.elements; ++e)
      for (const Vec3& p : wall_points(a, e)) walls.push_back(p);
    const MatrixXd w = void_surface->potentials(walls);
    void_rows = rows_from(a, kinds, w.cols(), [&](int i, Eigen::Index c) { return w(i, c); });
    b->void_rows = void_rows.transpose().cast<float>();
  }
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
  if (robin) b->layer_moments = MatrixXd::Zero(4, cols);
  if (void_surface && !void_surface->reaches(ch.axis.p0, ch.axis.p1, ch.radius) && robin) {
    b->void_tau = void_surface->layer(void_robin_rhs(a, b->moments));
    b->layer_moments = void_surface->moments() * b->void_tau.cast<double>();
    b->face_means += void_face_potentials * b->void_tau.cast<double>();  // its far lattice: in the solve
    if (!b->sample_cols_f.empty())
      add_skinny_product(void_potentials_ft, b->void_tau, Eigen::Map<Eigen::MatrixXf>(b->sample_cols_f.data(), Eigen::Index(n_samples), cols));
    else
      Eigen::Map<MatrixXd>(b->sample_cols_d.data(), Eigen::Index(n_samples), cols).noalias() +=
          *void_potentials * b->void_tau.cast<double>();
  } else if (void_surface && !void_surface->reaches(ch.axis.p0, ch.axis.p1, ch.radius)) {
    const Eigen::MatrixXf d = void_derivatives(a);
    b->void_tau = void_surface->layer(d);
    b->face_means += void_faces * d.cast<double>();
    if (!b->sample_cols_f.empty())
      add_skinny_product(void_potentials_ft, b->void_tau, Eigen::Map<Eigen::MatrixXf>(b->sample_cols_f.data(), Eigen::Index(n_samples), cols));
    else
      Eigen::Map<MatrixXd>(b->sample_cols_d.data(), Eigen::Index(n_samples), cols).noalias() +=
          *void_potentials * void_surface->solve(d.cast<double>());
  }
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
  if (b->void_tau.size()) b->self += void_at_rows(*b, *b);  // its own reflection in the void, a field from outside
  b->heat_rows.resize(cols);
  row_functionals(a, [&](const Vec3& p, double* v) { v[0] = heat_at(p); }, 1,
                  b->heat_rows.data(), cols);
  if (void_surface) b->heat_rows += void_rows * heat_tau;  // the heat input's correction
  b->far_rows.resize(cols, 4);
  row_functionals(a, [&](const Vec3& p, double* v) {
    const Eigen::Vector4d k = far_at(p);
    for (int i = 0; i < 4; ++i) v[i] = k[i];
  }, 4, b->far_rows.data(), cols);
  if (robin) {  // the layers' far lattice at the rows, and the fixed ones' fields there
    b->far_rows_layer.resize(cols, 4);
    row_functionals(a, [&](const Vec3& p, double* v) {
      const Eigen::Vector4d k = far_kernel(p, sample_far);
      for (int i = 0; i < 4; ++i) v[i] = k[i];
    }, 4, b->far_rows_layer.data(), cols);
    b->heat_rows += b->far_rows_layer * heat_layer_moments;
    b->t0_rows = void_rows * t0_tau + b->far_rows_layer * t0_moments;
    b->face_layer_rows = void_rows * face_tau + b->far_rows_layer * face_layer_moments;
  }
  b->face_rows.resize(cols, faces.size());
  if (!faces.empty())
    row_functionals(a, [&](const Vec3& p, double* v) {
      if (setting.block.contains(p)) return face_grid.interpolate(p, v);
      for (std::size_t f = 0; f < faces.size(); ++f) v[f] = face_field(faces[f], p);  // no extrapolation
    },
                    int(faces.size()), b->face_rows.data(), cols);
  if (robin && !faces.empty()) b->face_rows += b->face_layer_rows;
  return b;
}

}  // namespace mtcs::thermal
