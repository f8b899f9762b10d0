// One layout through the line-sink model: look up or build each channel's and pair's blocks,
// assemble the collocation system, solve it, and sum the columns at the samples.

#include "mtcs/thermal/line_sinks.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>
#include <span>
#include <stdexcept>

#include <absl/container/flat_hash_map.h>

#include "thermal/linalg/dense_solve.h"
#include "thermal/line_sinks/line_sink_model.h"
#include "mtcs/geometry/exact_hash.h"
#include "mtcs/geometry/segment_distance.h"

namespace mtcs::thermal {

namespace {

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

// A channel as the coolant's warming along its circuit sees it.
struct Warming {
  int circuit = -1;
  double position = 0, capacity = 0;  // W/K
  double w1 = 1;                      // the weight of its mean rows
  int first = 0, elements = 0, kinds = 1;  // its columns: element e's strength at first + e * kinds
  double element_length = 0;
};

// The coolant warms along its circuit: an element's coolant is the inlet's plus, over the
// circuit's capacity rate (rho Q c_p), the heat of every element upstream and half its own. Each
// mean row (the coolant on its right-hand side, weighted w1) gains those strengths' columns:
// lower-triangular within a circuit, so the system stays one solve.
void add_coolant_rise(std::span<const Warming> channels, MatrixXd& A) {
  for (const Warming& c : channels) {
    if (c.circuit < 0 || !(c.capacity > 0)) continue;
    const double per_watt = c.w1 / c.capacity;  // K of coolant per W, weighted
    for (int e = 0; e < c.elements; ++e) {
      const int row = c.first + e * c.kinds;
      for (const Warming& d : channels) {
        const bool self = &d == &c;
        if (d.circuit != c.circuit || !(self || d.position < c.position)) continue;
        for (int j = 0; j < (self ? e : d.elements); ++j) A(row, d.first + j * d.kinds) -= per_watt * d.element_length;
        if (self) A(row, row) -= per_watt * d.element_length / 2;
      }
    }
  }
}

}  // namespace

// The blocks by their exact geometry: flat tables (one probe into contiguous slots, no node
// per entry), keys compared bit for bit.
struct LineSinkCache::Tables {
  using Key = std::array<double, 7>;        // a channel: axis ends, radius
  using PairKey = std::array<double, 14>;   // rows' channel, columns' channel
  struct KeyHash {
    template <std::size_t N>
    std::size_t operator()(const std::array<double, N>& k) const {
      return geometry::exact_bits_hash(k.data(), N);
    }
  };
  struct KeyEqual {  // bits, as the hash: -0 and 0 are different keys (the same block, computed twice)
    template <std::size_t N>
    bool operator()(const std::array<double, N>& a, const std::array<double, N>& b) const {
      return std::memcmp(a.data(), b.data(), N * sizeof(double)) == 0;
    }
  };
  template <class Block>
  struct Entry {
    std::shared_ptr<Block> block;
    std::uint64_t used = 0;  // the evaluation that last used it
  };
  absl::flat_hash_map<Key, Entry<ChannelBlock>, KeyHash, KeyEqual> channels;
  absl::flat_hash_map<PairKey, Entry<PairBlock>, KeyHash, KeyEqual> pairs;
};

LineSinkCache::LineSinkCache(std::size_t budget_bytes) : tables_(std::make_unique<Tables>()), budget_(budget_bytes) {}
LineSinkCache::~LineSinkCache() = default;
LineSinkCache::LineSinkCache(LineSinkCache&&) noexcept = default;
LineSinkCache& LineSinkCache::operator=(LineSinkCache&&) noexcept = default;

void LineSinkCache::clear() {
  if (!tables_) tables_ = std::make_unique<Tables>();  // a moved-from cache
  tables_->channels.clear();
  tables_->pairs.clear();
  bytes_ = 0;
}

namespace {

// What a block holds, roughly (for the cache's budget).
std::size_t block_bytes(const LineSinkCache::ChannelBlock& b) {
  const auto& w = b.walls;
  return sizeof b + b.sample_cols_f.size() * sizeof(float) + b.sample_cols_d.size() * sizeof(double) +
         w.points.size() * (sizeof(WeightedPoint) + 3 * sizeof(float)) + w.sx.size() * 4 * sizeof(float) +
         std::size_t(b.face_means.size() + b.self.size() + b.face_rows.size() + b.far_rows.size() + b.moments.size() +
                     b.heat_rows.size() + b.cols) * sizeof(double) +
         std::size_t(b.void_tau.size() + b.void_rows.size()) * sizeof(float);
}
std::size_t block_bytes(const LineSinkCache::PairBlock& p) { return sizeof p + std::size_t(p.block.size()) * sizeof(double) + 64; }

// Drops the entries unused for longest until the map holds at most `keep` bytes; the entries of
// evaluation `now` stay.
template <class Map>
void shrink(Map& map, std::size_t& bytes, std::size_t keep, std::uint64_t now) {
  if (bytes <= keep) return;
  std::vector<std::uint64_t> ages;
  ages.reserve(map.size());
  for (const auto& [key, e] : map) ages.push_back(e.used);
  // Drop the older half of the entries (never the current evaluation's): the median age, no
  // full sort needed.
  std::nth_element(ages.begin(), ages.begin() + std::ptrdiff_t(ages.size() / 2), ages.end());
  const std::uint64_t cut = std::min(ages[ages.size() / 2], now);
  for (auto it = map.begin(); it != map.end();) {
    if (it->second.used < cut || (it->second.used == cut && cut < now)) {
      if (it->second.block) bytes -= block_bytes(*it->second.block);  // null: its build threw
      map.erase(it++);  // a flat table's erase leaves the other iterators valid
    } else {
      ++it;
    }
  }
}

// A bore running along a face closer than its radius breaks through it (a layout the optimiser
// may try: infeasible by bore_surface). Its image in that face would cross its own wall, where
// the line sources' fields are singular (NaN where a wall point falls on the image's axis, as at
// a 4 mm radius 2 mm under the face): the model lays it tangent to the face instead, a finite
// stand-in for a layout no one can build.
void keep_wall_inside(const geometry::Box& block, Channel& ch) {
  const Vec3 along = ch.axis.p1 - ch.axis.p0;
  const double length = along.norm();
  if (length == 0) return;
  for (int k = 0; k < 3; ++k) {
    if (std::abs(along[k]) > 1e-12 * length) continue;  // not parallel to the faces across k
    const double low = block.min[k] + ch.radius, high = block.max[k] - ch.radius;
    if (low > high) continue;  // a block thinner than the bore: nothing to lay it against
    const double x = ch.axis.p0[k], to = std::clamp(x, low, high);
    ch.axis.p0[k] = to, ch.axis.p1[k] = to;
  }
}

}  // namespace

LineSinkModel::~LineSinkModel() = default;
LineSinkModel::LineSinkModel(LineSinkModel&&) noexcept = default;
const LineSinkOptions& LineSinkModel::options() const { return impl_->options; }

LineSinkSolution LineSinkModel::solve(std::span<const Channel> channels, LineSinkCache& cache) const {
  const Impl& m = *impl_;
  if (cache.owner_ != impl_.get() || !cache.tables_) {
    cache.clear();
    cache.owner_ = impl_.get();
  }
  if (channels.empty() && !m.fixed_constant)
    throw std::invalid_argument("line sinks: no channel and no isothermal face: no steady state");
  // Only the steel conducts: a channel's part outside the block (a connection in the air) takes
  // no heat, and its images would land inside.
  thread_local std::vector<Channel> inside;  // per-thread scratch, as the system below
  inside.assign(channels.begin(), channels.end());
  for (Channel& ch : inside) {
    const auto clipped = clip_to_block(m.setting.block, ch.axis);
    if (!clipped) throw std::invalid_argument("line sinks: a channel lies outside the block");
    ch.axis = *clipped;
    keep_wall_inside(m.setting.block, ch);
  }
  // A channel inside another's bore (both its ends within that one's radius of its axis: a jog
  // of a few mm at a junction) has no steel wall: it takes no heat. Left in, its collocation
  // points sit in the other's coolant, a fraction of a mm from that line source, and the system
  // can come out near singular (thousands of K on a ribbed_box layout at 8 elements).
  const std::size_t given = inside.size();
  const auto within = [&](std::size_t c, std::size_t d) {  // c inside d's bore
    const geometry::Segment& s = inside[d].axis;
    return geometry::point_segment_distance(inside[c].axis.p0, s) < inside[d].radius &&
           geometry::point_segment_distance(inside[c].axis.p1, s) < inside[d].radius;
  };
  thread_local std::vector<std::size_t> kept;  // of the given channels, in order
  thread_local std::vector<char> dropped;
  kept.clear();
  dropped.assign(given, 0);
  for (std::size_t c = 0; c < given; ++c) {
    for (std::size_t d = 0; d < given && !dropped[c]; ++d)
      if (d != c && !dropped[d]) dropped[c] = within(c, d) && !(d > c && within(d, c));  // of two inside each other, the first stays
    if (!dropped[c]) kept.push_back(c);
  }
  if (kept.size() < given) {
    for (std::size_t k = 0; k < kept.size(); ++k) inside[k] = inside[kept[k]];
    inside.resize(kept.size());
  }
  channels = inside;
  const std::size_t nc = channels.size();
  // Look up or build every channel's and pair's blocks.
  using Key = LineSinkCache::Tables::Key;
  LineSinkCache::Tables& tables = *cache.tables_;
  const std::uint64_t now = ++cache.evaluation_;
  thread_local std::vector<Key> keys;
  keys.resize(nc);
  // Plain pointers into the cache: nothing leaves it before the shrink at the end.
  std::vector<const LineSinkCache::ChannelBlock*> blocks(nc);
  for (std::size_t c = 0; c < nc; ++c) {
    const Channel& ch = channels[c];
    if (!((ch.axis.p1 - ch.axis.p0).norm() > 0) || !(ch.radius > 0))
      throw std::invalid_argument("line sinks: a channel needs a positive length and radius");
    keys[c] = {ch.axis.p0.x(), ch.axis.p0.y(), ch.axis.p0.z(), ch.axis.p1.x(), ch.axis.p1.y(),
               ch.axis.p1.z(), ch.radius};
    auto& entry = tables.channels[keys[c]];
    if (entry.block) {
      ++cache.channels_reused;
    } else {
      entry.block = m.build_channel(ch);
      cache.bytes_ += block_bytes(*entry.block);
      ++cache.channels_computed;
    }
    entry.used = now;
    blocks[c] = entry.block.get();
  }
  // Every ordered pair's block (rows of r, columns of c), looked up once.
  std::vector<const LineSinkCache::PairBlock*> pairs(nc * nc);
  for (std::size_t r = 0; r < nc; ++r)
    for (std::size_t c = 0; c < nc; ++c) {
      if (r == c) continue;
      LineSinkCache::Tables::PairKey k;
      std::copy(keys[r].begin(), keys[r].end(), k.begin());
      std::copy(keys[c].begin(), keys[c].end(), k.begin() + 7);
      auto& entry = tables.pairs[k];
      if (!entry.block) {
        entry.block = std::make_shared<LineSinkCache::PairBlock>();
        entry.block->block = m.channel_at_rows(*blocks[r], *blocks[c]);
        cache.bytes_ += block_bytes(*entry.block);
      }
      entry.used = now;
      pairs[r * nc + c] = entry.block.get();
    }

  // Unknowns: the channels' columns, the faces' losses, the free constant.
  thread_local std::vector<int> offset;
  offset.assign(nc + 1, 0);
  for (std::size_t c = 0; c < nc; ++c) offset[c + 1] = offset[c] + blocks[c]->cols;
  const int n_ch = offset[nc];
  const int nf = int(m.faces.size());
  const bool free_constant = !m.fixed_constant;
  const int n = n_ch + nf + (free_constant ? 1 : 0);
  const int t0 = n_ch + nf;  // column of the free constant
  const double fixed = m.fixed_constant.value_or(0.0);
  const double k = m.setting.conductivity;
  // The system's storage is the thread's, kept between solves (a 40 kB malloc and free each).
  thread_local MatrixXd A;
  thread_local VectorXd rhs;
  A.setZero(n, n);
  rhs.setZero(n);

  thread_local std::vector<Warming> warming;
  warming.clear();
  for (std::size_t c = 0; c < nc; ++c) {
    const auto& b = *blocks[c];
    const Channel& ch = channels[c];
    const double R = b.axis.radius, h = ch.film;
    const double w1 = h == kInfiniteFilm ? 1 : h * R / (k + h * R);
    warming.push_back({ch.circuit, ch.position, ch.capacity, w1, offset[c], b.axis.elements, m.kinds, b.axis.element_length});
    const double w2 = h == kInfiniteFilm ? 0 : 1 / (2 * std::numbers::pi * (k + h * R));
    const double beta = h == kInfiniteFilm ? -1 : (k - h * R) / (k + h * R);
    // The rows' fields, block by block: each channel's columns and each face's loss, near part
    // plus the far lattice (the rows' far kernel times the sources' moments); then each row
    // weighted as its condition needs.
    for (std::size_t d = 0; d < nc; ++d) {
      auto to = A.block(offset[c], offset[d], b.cols, blocks[d]->cols);
      to = b.far_rows.lazyProduct(blocks[d]->moments);  // coefficient-wise: 4 terms, no GEMM set-up
      to += d == c ? b.self : pairs[c * nc + d]->block;
      if (m.robin) to += b.far_rows_layer.lazyProduct(blocks[d]->layer_moments);
    }
    if (nf) {
      auto to = A.block(offset[c], n_ch, b.cols, nf);
      to = b.far_rows.lazyProduct(m.face_moments);
      to += b.face_rows;
    }
    const VectorXd heat_rows = b.heat_rows + b.far_rows * m.heat_moments;
    for (int r = 0; r < b.cols; ++r) {
      const int row = offset[c] + r;
      const bool mean_row = r % m.kinds == 0;
      // The free constant's field at the row: 1, and with a film its layer's.
      const double constant = (mean_row ? 1.0 : 0.0) + (m.robin ? b.t0_rows[r] : 0.0);
      A.row(row).head(n_ch + nf) *= mean_row ? w1 : -beta;  // the weight of the field in this row
      if (mean_row) {
        A(row, row) -= w2;  // the film's drop: q' / (2 pi R h)
        if (free_constant) A(row, t0) = w1 * constant;
        rhs[row] = w1 * (ch.coolant - heat_rows[r] - fixed * constant);
      } else {
        A(row, row) += b.self_dipole[r];
        if (free_constant && m.robin) A(row, t0) = -beta * constant;
        rhs[row] = beta * (heat_rows[r] + fixed * constant);
      }
    }
  }
  add_coolant_rise(warming, A);
  for (int f = 0; f < nf; ++f) {
    const ConvectiveFace& cf = m.faces[f];
    const int row = n_ch + f;
    // loss / (h A_conv) - face mean temperature = - ambient
    const Eigen::RowVector4d far_ch = m.far_face_means.row(f), far = m.far_face_means_fixed.row(f);
    for (std::size_t c = 0; c < nc; ++c) {
      A.block(row, offset[c], 1, blocks[c]->cols) = -(blocks[c]->face_means.row(f) + far_ch * blocks[c]->moments);
      if (m.robin) A.block(row, offset[c], 1, blocks[c]->cols) -= far_ch * blocks[c]->layer_moments;
    }
    for (int f2 = 0; f2 < nf; ++f2) A(row, n_ch + f2) = -(m.face_face_means(f, f2) + far.dot(m.face_moments.col(f2)));
    A(row, row) += cf.area / (cf.film * cf.convective_area);
    const double t0_mean = 1 + (m.robin ? m.t0_face_means[f] : 0.0);
    if (free_constant) A(row, t0) = -t0_mean;
    rhs[row] = m.heat_face_means[f] + far.dot(m.heat_moments) + fixed * t0_mean - cf.ambient;
  }
  if (free_constant && m.robin) {  // the energy balance: every charge sums to 0, the layers' too
    for (std::size_t c = 0; c < nc; ++c)
      A.block(t0, offset[c], 1, blocks[c]->cols) = -(blocks[c]->moments.row(0) + blocks[c]->layer_moments.row(0));
    for (int f = 0; f < nf; ++f) A(t0, n_ch + f) = -(m.face_moments(0, f) + m.face_layer_moments(0, f));
    A(t0, t0) = -m.t0_moments[0];
    rhs[t0] = m.heat_in + m.heat_layer_moments[0];
  } else if (free_constant) {  // the energy balance fixes the constant
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
    x = solve_dense(A, rhs);
  }

  LineSinkSolution out;
  out.heat_in = m.heat_in;
  const double T0 = free_constant ? x[t0] : fixed;
  out.temperature.resize(m.n_samples);
  Eigen::Map<VectorXd> T(out.temperature.data(), Eigen::Index(m.n_samples));
  T = m.heat_samples + VectorXd::Constant(m.n_samples, T0);
  if (m.robin) T += T0 * m.t0_samples;
  if (nf) T += m.face_samples * x.segment(n_ch, nf);
  // The far lattice: the moments of everything in the block (the layers' with the channels'
  // lattice; the fixed and face layers' are in heat_samples and face_samples already).
  Eigen::Vector4d fixed_moments = m.heat_moments, channel_moments = Eigen::Vector4d::Zero();
  for (int f = 0; f < nf; ++f) fixed_moments += x[n_ch + f] * m.face_moments.col(f);
  for (std::size_t c = 0; c < nc; ++c) {
    channel_moments += blocks[c]->moments * x.segment(offset[c], blocks[c]->cols);
    if (m.robin) channel_moments += blocks[c]->layer_moments * x.segment(offset[c], blocks[c]->cols);
  }
  T += m.far_samples_fixed * fixed_moments + m.far_samples * channel_moments;
  if (m.robin) {  // the heat the part gives: the layers' charges
    out.heat_in += m.heat_layer_moments[0] + T0 * m.t0_moments[0];
    for (int f = 0; f < nf; ++f) out.heat_in += x[n_ch + f] * m.face_layer_moments(0, f);
    for (std::size_t c = 0; c < nc; ++c)
      out.heat_in += blocks[c]->layer_moments.row(0).dot(x.segment(offset[c], blocks[c]->cols));
  }
  const std::size_t ns = m.n_samples;
  out.channel_heat.reserve(nc);
  for (std::size_t c = 0; c < nc; ++c) {
    const auto& b = *blocks[c];
    if (m.options.single_precision) {
      accumulate_float_columns(b.sample_cols_f.data(), ns, b.cols, x.data() + offset[c], T.data());
    } else {
      for (int col = 0; col < b.cols; ++col) {
        const double xi = x[offset[c] + col];
        const double* v = &b.sample_cols_d[col * ns];
        for (std::size_t s = 0; s < ns; ++s) T[s] += xi * v[s];
      }
    }
    double q = 0;
    for (int e = 0; e < b.axis.elements; ++e) q += x[offset[c] + e * m.kinds] * b.axis.element_length;
    out.channel_heat.push_back(q);
  }
  for (int f = 0; f < nf; ++f) out.face_heat += x[n_ch + f] * m.faces[f].area;
  if (kept.size() < given) {  // one entry per given channel: 0 for those inside another
    std::vector<double> heat(given, 0.0);
    for (std::size_t k = 0; k < kept.size(); ++k) heat[kept[k]] = out.channel_heat[k];
    out.channel_heat = std::move(heat);
  }

  // Over budget: the blocks unused for longest go (the pairs first: cheaper to rebuild).
  if (cache.bytes_ > cache.budget_) {
    shrink(tables.pairs, cache.bytes_, cache.budget_ / 2, now);
    shrink(tables.channels, cache.bytes_, cache.budget_ / 2, now);
  }
  return out;
}

}  // namespace mtcs::thermal
