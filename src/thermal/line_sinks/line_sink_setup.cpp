// The line-sink model's build (once per setting and samples): the image lattice, the convective
// faces, the samples expanded by their images, and the layout-independent fields (heat input,
// face losses, far lattice) at the samples and on grids over the block.

#include <algorithm>
#include <cmath>
#include <deque>
#include <mutex>
#include <numbers>
#include <numeric>
#include <stdexcept>

#include <tbb/parallel_for.h>

#include "thermal/kernels/heat_source_tree.h"
#include "thermal/line_sinks/line_sink_model.h"
#include "thermal/line_sinks/model_memory.h"

namespace mtcs::thermal {

namespace {

// The heat tree's opening angle: a group of triangles takes its expansion beyond 1 / theta of
// its radius. Against the direct sum, `mtcs thermal` on the bundled mesh molds moves by at most
// 0.005 K (ribbed_box's max; experiments/thermal/heat_tree.md), its model built in 3.2 s
// instead of 35 s.
constexpr double kHeatTreeTheta = 0.15;
// far_lattice_misfit above which the samples sum every exact level: the bundled molds measure
// 0.07-2.2 %, the channel row of experiments/thermal/published_menges 34 % (its temperatures
// along the bores 32-49 C with one level, 37.5-39.7 C with two; T3 37.4-39.5 C).
constexpr double kFarMisfitBound = 0.05;

// f(p, values) for every node p of g, with the node's g.fields values to write; rows of nodes in
// parallel. Each node's values are its own: the table is the same whatever the threads. The
// tables cost nodes x heated triangles x images triangle potentials (seconds on a large block).
template <class F>
void fill_nodes(FieldGrid& g, const F& f) {
  const int rows = g.nodes[1] * g.nodes[2];
  tbb::parallel_for(0, rows, [&](int r) {
    const int j = r % g.nodes[1], k = r / g.nodes[1];
    double* values = g.values.data() + std::size_t(r) * std::size_t(g.nodes[0]) * std::size_t(g.fields);
    for (int i = 0; i < g.nodes[0]; ++i, values += g.fields) f(g.origin + g.step.cwiseProduct(Vec3(i, j, k)), values);
  });
}

// f(i) for i in [0, n), in parallel: per-sample fields, each written by its own index.
template <class F>
void for_each_index(std::size_t n, const F& f) {
  tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) { f(i); });
}

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

// The tabulated heat input and far lattice depend on the setting and the options, not on the
// samples, and cost seconds on a large cavity (~8 s of CPU on the physics plate): models of one
// setting built in one process (a report's pipeline and its temperature field, a run's
// screening pipeline) share one build, copied. The last few builds are kept.
struct Tables {
  FieldGrid far_grid, heat_grid, heat_fine;
  Box heat_fine_box = Box::empty(), heat_near = Box::empty();
  std::vector<Image> near_heat_images, far_heat_images;
};

// `key` followed by every number of the setting a kept build depends on: the block, its faces'
// conditions, the heated triangles (and their film and part temperature: `with_film`).
std::vector<double> setting_key(const Setting& setting, std::vector<double> key, bool with_film = true) {
  key.push_back(setting.conductivity);
  for (const Vec3& v : {setting.block.min, setting.block.max}) key.insert(key.end(), v.data(), v.data() + 3);
  for (const FaceCondition& f : setting.faces) key.push_back(f.film), key.push_back(f.ambient);
  for (const HeatedTriangle& t : setting.heat_in) {
    for (const Vec3& v : {t.a, t.b, t.c}) key.insert(key.end(), v.data(), v.data() + 3);
    key.push_back(t.flux);
    if (with_film) key.push_back(t.film), key.push_back(t.part_temperature);
  }
  return key;
}

// Every number the tables depend on, in order: equal keys, equal tables. Not the part's film:
// the tables hold the heat input's flux and the images (mtcs thermal's cycle reuses them).
std::vector<double> tables_key(const Setting& setting, const LineSinkOptions& options) {
  return setting_key(setting, {double(options.images), double(options.far_images), options.heat_grid}, false);
}

std::mutex tables_mutex;
std::deque<std::pair<std::vector<double>, std::shared_ptr<const Tables>>> tables_kept;  // newest first

std::shared_ptr<const Tables> kept_tables(const std::vector<double>& key) {
  const std::lock_guard lock(tables_mutex);
  for (const auto& [k, t] : tables_kept)
    if (k == key) return t;
  return nullptr;
}

void keep_tables(std::vector<double> key, Tables tables) {
  auto t = std::make_shared<const Tables>(std::move(tables));
  const std::lock_guard lock(tables_mutex);
  tables_kept.emplace_front(std::move(key), std::move(t));
  if (tables_kept.size() > 4) tables_kept.pop_back();
}

// A patch's panels (mm) when thermal.void_panel does not say: ~200 on the reference block's.
constexpr double kPatchPanel = 4;

// Whether every heated triangle lies on a face of the block (a patch: the melt outside).
bool on_block_faces(const Setting& setting) {
  const Box& b = setting.block;
  const double tol = 1e-9 * (1 + b.size().norm() + b.max.cwiseAbs().maxCoeff());
  auto on = [&](const HeatedTriangle& t, int axis, double plane) {
    return std::abs(t.a[axis] - plane) <= tol && std::abs(t.b[axis] - plane) <= tol && std::abs(t.c[axis] - plane) <= tol;
  };
  return std::all_of(setting.heat_in.begin(), setting.heat_in.end(), [&](const HeatedTriangle& t) {
    for (int axis = 0; axis < 3; ++axis)
      if (on(t, axis, b.min[axis]) || on(t, axis, b.max[axis])) return true;
    return false;
  });
}

// The part's void likewise (seconds on a mesh cavity): a run's screening pipeline with samples of
// its own, or `mtcs thermal --out`'s field, solves the same void as the model before it. Kept by
// every number it depends on; the newest two.
std::mutex voids_mutex;
std::deque<std::pair<std::vector<double>, std::shared_ptr<const VoidSurface>>> voids_kept;  // newest first

std::shared_ptr<const VoidSurface> kept_void(const Setting& setting, const std::vector<Image>& images, int sample_levels,
                                             double panel, int far_levels, const FarLattice& far, bool on_block_face) {
  std::vector<double> key = setting_key(setting, {double(sample_levels), panel, double(far_levels), double(on_block_face)});
  {
    const std::lock_guard lock(voids_mutex);
    for (const auto& [k, v] : voids_kept)
      if (k == key) return v;
  }
  auto v = std::make_shared<const VoidSurface>(setting.heat_in, images, panel, setting.conductivity, far, on_block_face);
  const std::lock_guard lock(voids_mutex);
  voids_kept.emplace_front(std::move(key), v);
  if (voids_kept.size() > 2) voids_kept.pop_back();
  return v;
}

// How far the far lattice's charge and dipole miss the heated wall's own images at the samples,
// relative to the wall's range of potential there: the wall at unit flux (its geometry alone),
// exact to `levels` against exact to `near` plus the lattice of `far` (its uniform part left out:
// the free constant or the faces take it). Near 0 when the sources are compact within the block
// (the reference block: 0.5 %); large when they reach two faces, as a cavity over a whole face
// (the channel row of experiments/thermal/published_menges: 34 %), where the bores' images past
// the edges lie beside the samples and must be summed exactly too.
constexpr std::size_t kMisfitSamples = 256;
double far_lattice_misfit(const Setting& setting, const Samples& samples, const Box& box,
                          const std::array<double, 6>& sign, int near, int levels) {
  std::vector<HeatedTriangle> wall;
  for (const HeatedTriangle& t : setting.heat_in)
    if (t.heats()) wall.push_back({t.a, t.b, t.c, 1.0});
  if (wall.empty() || samples.size() == 0 || levels <= near) return 0;
  const HeatSourceTree tree(wall, kHeatTreeTheta);
  const Vec3 center = 0.5 * (box.min + box.max);
  Eigen::Vector4d moments = Eigen::Vector4d::Zero();
  for (const HeatedTriangle& t : wall) {
    const double area = 0.5 * (t.b - t.a).cross(t.c - t.a).norm();
    moments[0] += area;
    moments.tail<3>() += area * ((t.a + t.b + t.c) / 3 - center);
  }
  const std::vector<Image> exact = block_images(box, sign, levels), nearer = block_images(box, sign, near);
  std::vector<Image> far = block_images(box, sign, levels);
  far.erase(far.begin(), far.begin() + std::ptrdiff_t(nearer.size()));
  const auto sum = [&](std::span<const Image> of, const Vec3& p) {
    double v = 0;
    for (const Image& g : of) v += g.sign * tree.potential(g.mult.cwiseProduct(p) + g.offset);
    return v;
  };
  // Every k-th sample of weight (points of no weight, such as those across the part, left out:
  // the pipeline's samples and mtcs thermal's then decide alike); the misfit is a property of
  // the geometry, not of one sample.
  std::vector<std::size_t> weighted;
  for (std::size_t i = 0; i < samples.size(); ++i)
    if (samples.weights.empty() || samples.weights[i] > 0) weighted.push_back(i);
  if (weighted.empty()) return 0;
  const std::size_t stride = (weighted.size() + kMisfitSamples - 1) / kMisfitSamples, n = (weighted.size() + stride - 1) / stride;
  std::vector<double> truth(n), miss(n);
  for_each_index(n, [&](std::size_t s) {
    const Vec3& p = samples.points[weighted[s * stride]];
    truth[s] = sum(exact, p);
    miss[s] = truth[s] - sum(nearer, p) - far_lattice_kernel(far, center, p).dot(moments);
  });
  const double mean = std::accumulate(miss.begin(), miss.end(), 0.0) / double(n);
  double worst = 0;
  for (const double d : miss) worst = std::max(worst, std::abs(d - mean));
  const auto [lo, hi] = std::minmax_element(truth.begin(), truth.end());
  return *hi > *lo ? worst / (*hi - *lo) : 0;
}

}  // namespace

void LineSinkModel::Impl::build_robin_fields(const MatrixXd& at_faces, const MatrixXd& d) {
  Impl& m = *this;
  const VoidSurface& v = *void_surface;
  const std::size_t n = v.panels(), nf = m.faces.size();
  const auto N = Eigen::Index(n);
  const VectorXd& H = v.film_over_k();
  m.void_face_potentials = m.face_average * at_faces;
  m.far_panels.resize(N, 4);
  MatrixXd far_fixed(N, 4);  // the far lattice of the sources summed to `images` levels
  VectorXd heat(N);
  MatrixXd face(N, Eigen::Index(nf));
  for_each_index(n, [&](std::size_t i) {
    const Vec3& p = v.points()[i];
    const auto r = Eigen::Index(i);
    m.far_panels.row(r) = m.far_kernel(p, m.sample_far).transpose();
    far_fixed.row(r) = m.far_kernel(p).transpose();
    heat[r] = m.heat_field(p);
    for (std::size_t f = 0; f < nf; ++f) face(r, Eigen::Index(f)) = m.face_field(m.faces[f], p);
  });
  // The fixed sources: the sheets' derivative and the film's answer to their field, and the
  // part's temperature driving the film.
  const VectorXd heat_f = heat + far_fixed * m.heat_moments;
  m.heat_tau = v.solve(v.heat_derivatives() + H.cwiseProduct(v.part_temperatures() - heat_f));
  m.heat_layer_moments = v.moments() * m.heat_tau;
  // The free constant: a unit field everywhere, so the film takes -H from it.
  m.t0_tau = v.solve(-H);
  m.t0_moments = v.moments() * m.t0_tau;
  m.t0_samples = *m.void_potentials * m.t0_tau + m.far_samples * m.t0_moments;
  m.t0_face_means = m.void_face_potentials * m.t0_tau + m.far_face_means * m.t0_moments;
  // The face losses.
  m.face_tau = v.solve(d - H.asDiagonal() * (face + far_fixed * m.face_moments));
  m.face_layer_moments = v.moments() * m.face_tau;
  m.face_samples += *m.void_potentials * m.face_tau + m.far_samples * m.face_layer_moments;
  m.face_void = m.void_face_potentials * m.face_tau + m.far_face_means * m.face_layer_moments;
}

LineSinkModel::LineSinkModel(const LineSinkModel& like, const Samples& samples, bool keep_potentials)
    : LineSinkModel(like.impl_->setting, samples, [&] {
        LineSinkOptions o = like.impl_->options;
        o.keep_potentials = keep_potentials;
        return o;
      }()) {}

LineSinkModel::LineSinkModel(const Setting& setting, const Samples& samples, LineSinkOptions options)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  if (options.elements < 1 || options.elements > 64)
    throw std::invalid_argument("line sinks: elements per channel must be in 1..64");
  if (options.images < 0) throw std::invalid_argument("line sinks: images must be >= 0");
  if (!(options.far_expansion >= 0 && options.far_expansion <= 0.5))
    throw std::invalid_argument("line sinks: far_expansion must be in [0, 0.5]");
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
    sign[f] = fc.film == kInfiniteFilm ? -1 : 1;
    if (fc.film == kInfiniteFilm) {
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
  // far lattice's charge and dipole; all of them where that lattice misses the heated wall.
  int sample_levels = options.sample_images < 0 ? options.images : std::min(options.sample_images, options.images);
  if (options.sample_images == 0) {
    sample_levels = far_lattice_misfit(setting, samples, box, sign, 1, options.images) > kFarMisfitBound ? options.images
                                                                                                       : std::min(1, options.images);
    m.options.sample_images = std::max(sample_levels, 1);  // decided once: a model `like` this one sums the same
  }
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
    if (t.flux != 0) m.heat_sources.push_back({TriangleSource(t.a, t.b, t.c), t.flux});
  }
  if (m.heat_sources.size() > Impl::kTreeAbove) m.heat_tree.emplace(setting.heat_in, kHeatTreeTheta);
  // The part's void (void_surface.h).
  m.sample_far = sample_far;
  const FarLattice far{[&m](const Vec3& p) { return m.far_kernel(p, m.sample_far); }, m.center};
  const bool films = std::any_of(setting.heat_in.begin(), setting.heat_in.end(), [](const HeatedTriangle& t) { return t.film > 0; });
  if (options.void_panel > 0 && (setting.cavity_mesh || setting.cavity_box) && !setting.heat_in.empty()) {
    m.void_surface = kept_void(setting, sample_images, sample_levels, options.void_panel, options.far_images, far, false);
    m.robin = m.void_surface->robin();
  } else if (films && !setting.cavity_mesh && !setting.cavity_box && on_block_faces(setting)) {
    // A patch with the part's film: its panels carry the film's flux.
    const double panel = options.void_panel > 0 ? options.void_panel : kPatchPanel;
    m.void_surface = kept_void(setting, sample_images, sample_levels, panel, options.far_images, far, true);
    m.robin = true;
  }
  for (const HeatedTriangle& t : setting.heat_in)
    if (t.film > 0 && !m.robin)
      throw std::invalid_argument(
          "line sinks: the part's coupling (a film on the cavity) needs the part's void as a surface "
          "(thermal.cavity_void: surface) or a patch on a block face; use thermal.tier: fd or cavity_condition: flux");

  // Convective faces: one unknown uniform loss each, collocated on a grid of the face's part
  // that is not heated.
  const auto corners = face_corners(box);
  const int g = std::max(1, options.face_grid);
  for (int f = 0; f < 6; ++f) {
    const FaceCondition& fc = setting.faces[f];
    if (!(fc.film > 0) || fc.film == kInfiniteFilm) continue;
    ConvectiveFace cf;
    cf.face = f;
    cf.film = fc.film;
    cf.ambient = fc.ambient;
    cf.corners = corners[f];
    cf.halves = {TriangleSource(cf.corners[0], cf.corners[1], cf.corners[2]),
                 TriangleSource(cf.corners[0], cf.corners[2], cf.corners[3])};
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
  if (m.n_samples) m.sample_set.make_slots(), m.sample_set.make_chunk_boxes();
  if (!m.faces.empty()) m.face_set.make_slots(), m.face_set.make_chunk_boxes();
  m.face_average = MatrixXd::Zero(m.faces.size(), m.face_set.targets());
  for (std::size_t f = 0, point = 0; f < m.faces.size(); ++f)
    for (std::size_t i = 0; i < m.faces[f].cool.size(); ++i) m.face_average(f, point++) = 1.0 / double(m.faces[f].cool.size());
  const std::size_t nf = m.faces.size();
  m.face_moments.resize(4, Eigen::Index(nf));
  for (std::size_t f = 0; f < nf; ++f) {
    const ConvectiveFace& cf = m.faces[f];
    m.face_moments.col(Eigen::Index(f)) << -cf.area, -cf.area * (cf.center - m.center);
  }
  m.far_samples.resize(m.n_samples, 4);
  m.far_samples_fixed.resize(m.n_samples, 4);
  for_each_index(m.n_samples, [&](std::size_t s) {
    m.far_samples.row(s) = m.far_kernel(samples.points[s], sample_far).transpose();
    m.far_samples_fixed.row(s) = m.far_kernel(samples.points[s]).transpose();
  });
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
    fill_nodes(g, [&](const Vec3& p, double* v) {
      for (std::size_t f = 0; f < nf; ++f) v[f] = m.face_field(m.faces[f], p);
    });
  }
  // Tabulated fields over the block: `heat_grid` mm, at most kCoarseCells per axis (a large
  // block gets a coarser spacing). Built once: nodes x heated triangles x images triangle
  // potentials, so a large block's heat input gets a second, finer grid (`heat_grid` mm, at
  // most kFineCells per axis) only around the heated triangles, where the coarse grid's exact
  // zone would otherwise catch every bore near the cavity.
  constexpr int kCoarseCells = 32, kFineCells = 80;
  const bool grids = options.heat_grid > 0;
  auto grid_over = [&](FieldGrid& g, const Box& region, int fields, int max_cells) {
    g.origin = region.min;
    g.fields = fields;
    for (int a = 0; a < 3; ++a) {
      const int cells = std::clamp(int(std::ceil(region.size()[a] / options.heat_grid)), 3, max_cells);
      g.nodes[a] = cells + 1;
      g.step[a] = region.size()[a] / cells;
    }
    g.values.resize(std::size_t(g.nodes[0]) * g.nodes[1] * g.nodes[2] * fields);
  };
  auto fill_heat = [&](FieldGrid& g) {  // per node: the whole field, the far images' part
    fill_nodes(g, [&](const Vec3& p, double* v) {
      const double far = m.heat_field(p, m.far_heat_images);
      v[0] = m.heat_field(p, m.near_heat_images) + far;
      v[1] = far;
    });
  };
  // Near images: those whose heated triangles come within 3 cells (of the grid interpolating
  // there) of heat_near; the others are smooth there and join the tables.
  auto split_heat_images = [&](const Box& bounds, double cell) {
    const Box near{m.heat_near.min.cwiseMax(box.min), m.heat_near.max.cwiseMin(box.max)};
    m.near_heat_images.clear(), m.far_heat_images.clear();
    for (const Image& im : m.images) {
      const Vec3 a = im.mult.cwiseProduct(bounds.min) + im.offset, b = im.mult.cwiseProduct(bounds.max) + im.offset;
      const Box image_bounds{a.cwiseMin(b), a.cwiseMax(b)};
      const bool far = box_distance_sq(image_bounds, near) >= 9 * cell * cell;
      (far ? m.far_heat_images : m.near_heat_images).push_back(im);
    }
  };
  const std::vector<double> key = grids ? tables_key(setting, options) : std::vector<double>{};
  const std::shared_ptr<const Tables> kept = grids ? kept_tables(key) : nullptr;
  if (kept) {
    m.far_grid = kept->far_grid, m.heat_grid = kept->heat_grid, m.heat_fine = kept->heat_fine;
    m.heat_fine_box = kept->heat_fine_box, m.heat_near = kept->heat_near;
    m.near_heat_images = kept->near_heat_images, m.far_heat_images = kept->far_heat_images;
  }
  if (!m.far_images.empty() && grids && !kept) {
    FieldGrid& g = m.far_grid;
    grid_over(g, box, 4, kCoarseCells);
    fill_nodes(g, [&](const Vec3& p, double* v) {
      const Eigen::Vector4d k = m.far_kernel(p);
      for (int c = 0; c < 4; ++c) v[c] = k[c];
    });
  }
  if (!setting.heat_in.empty() && grids && !kept) {
    Box bounds = Box::empty();
    for (const HeatedTriangle& t : setting.heat_in)
      for (const Vec3& v : {t.a, t.b, t.c}) bounds.min = bounds.min.cwiseMin(v), bounds.max = bounds.max.cwiseMax(v);
    FieldGrid& g = m.heat_grid;
    grid_over(g, box, 2, kCoarseCells);
    const Vec3 margin = Vec3::Constant(2 * g.step.maxCoeff());
    m.heat_near = {bounds.min - margin, bounds.max + margin};
    double near_cell = g.step.maxCoeff();
    if (g.step.maxCoeff() > 1.01 * options.heat_grid) {
      const Box region{m.heat_near.min.cwiseMax(box.min), m.heat_near.max.cwiseMin(box.max)};
      if ((region.size().array() > 0).all()) {
        m.heat_fine_box = region;
        grid_over(m.heat_fine, region, 2, kFineCells);
        const Vec3 fine_margin = Vec3::Constant(2 * m.heat_fine.step.maxCoeff());
        m.heat_near = {bounds.min - fine_margin, bounds.max + fine_margin};
        near_cell = m.heat_fine.step.maxCoeff();
      }
    }
    split_heat_images(bounds, near_cell);
    fill_heat(g);
    if (!m.heat_fine.values.empty()) fill_heat(m.heat_fine);
  }
  if (grids && !kept)
    keep_tables(key, {m.far_grid, m.heat_grid, m.heat_fine, m.heat_fine_box, m.heat_near, m.near_heat_images, m.far_heat_images});
  m.heat_samples.resize(m.n_samples);
  m.face_samples.resize(m.n_samples, nf);
  for_each_index(m.n_samples, [&](std::size_t s) {
    m.heat_samples[s] = m.heat_field(samples.points[s]);
    for (std::size_t f = 0; f < nf; ++f) m.face_samples(s, f) = m.face_field(m.faces[f], samples.points[s]);
  });
  if (m.void_surface) {
    // The samples' and faces' response to the panels, and the face losses' correction.
    const VoidSurface& v = *m.void_surface;
    m.void_step = 1e-2 * v.panel();
    for (std::size_t i = 0; i < v.panels(); ++i)
      for (const double side : {1.0, -1.0}) {
        m.void_pairs.add(sample_images, v.points()[i] + side * m.void_step * v.normals()[i], m.tol, 1.0, m.sample_origin);
        m.void_pairs.close_target();
      }
    m.void_pairs.make_slots(), m.void_pairs.make_chunk_boxes();
    check_void_model_memory(v.panels(), m.n_samples);
    m.void_potentials = options.keep_potentials ? v.kept_potentials(samples.points)
                                                : std::make_shared<const MatrixXd>(v.potentials(samples.points));
    m.void_potentials_ft = m.void_potentials->transpose().cast<float>();
    std::vector<Vec3> face_points;
    for (const ConvectiveFace& f : m.faces) face_points.insert(face_points.end(), f.cool.begin(), f.cool.end());
    const std::shared_ptr<const MatrixXd> at_faces = v.kept_potentials(face_points);
    m.void_faces = v.times_inverse(m.face_average * *at_faces);
    MatrixXd d(Eigen::Index(v.panels()), Eigen::Index(nf));
    for (std::size_t i = 0; i < v.panels(); ++i)
      for (std::size_t f = 0; f < nf; ++f)
        d(Eigen::Index(i), Eigen::Index(f)) = (m.face_field(m.faces[f], v.points()[i] + m.void_step * v.normals()[i]) -
                                               m.face_field(m.faces[f], v.points()[i] - m.void_step * v.normals()[i])) /
                                              (2 * m.void_step);
    if (v.on_block_face()) d.setZero();  // the face's image keeps every flux there
    if (m.robin) {
      m.build_robin_fields(*at_faces, d);
    } else {
      m.face_samples += *m.void_potentials * v.solve(d);
      m.face_void = m.void_faces * d;
      m.heat_tau = v.heat_layer();
    }
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
  if (m.void_surface && m.robin) {  // the layers' fields (robin_fixed_fields)
    m.face_face_means += m.face_void;
    m.heat_samples += *m.void_potentials * m.heat_tau + m.far_samples * m.heat_layer_moments;
    m.heat_face_means += m.void_face_potentials * m.heat_tau + m.far_face_means * m.heat_layer_moments;
  } else if (m.void_surface) {  // the void's correction of the face losses and of the heat input
    m.face_face_means += m.face_void;
    m.heat_samples += *m.void_potentials * m.void_surface->heat_layer();
    m.heat_face_means += m.void_faces * m.void_surface->heat_derivatives();
  }
}

}  // namespace mtcs::thermal
