// The per-direction octree traversal of every method, the per-map preparation (node centres
// relative to the pivot, memoised cone intervals) and the parallel loop over directions.

#include "mtcs/voxel/accessibility_map.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <optional>
#include <cmath>
#include <stdexcept>

#include "check_box.h"
#include "ica.h"

namespace mtcs::voxel {
namespace {

using detail::NodeCone;
using detail::SphereVerdict;

// A cube on the traversal stack: a stored node, or an octant of a full node or of a voxel
// (node = kVirtual), whose closed box the traversal keeps beside the stack (octants split at the
// midpoint, so they cover their parent exactly).
struct Cube {
  static constexpr std::uint32_t kVirtual = 0xffffffffu;
  std::uint32_t node;
  std::uint8_t level;  // may exceed the octree depth for octants of voxels
  std::uint8_t full;
};

// Number of set bits of a byte (no popcount instruction in the baseline x86-64 target).
constexpr std::array<std::uint8_t, 256> kBitCount = [] {
  std::array<std::uint8_t, 256> t{};
  for (int i = 0; i < 256; ++i) t[std::size_t(i)] = std::uint8_t((i & 1) + t[std::size_t(i / 2)]);
  return t;
}();

struct Counters {
  std::uint64_t node_tests = 0, checkbox_calls = 0, quad = 0, undecided = 0;
};

// Everything that does not depend on the direction.
struct Prepared {
  const Octree& tree;
  const Tool& tool;
  Vec3 pivot;
  AmMethod method;
  int last_level = 0;                // deepest level a corner case is expanded to (aica)
  std::vector<NodeCone> cone;        // for nodes [0, memo_end)
  std::vector<char> use_cone;        // cone valid (centre not too near the pivot)
  std::uint32_t memo_end = 0;
  std::vector<double> in2, out2;     // per level: squared test radii of the spheres

  // `box` is read only for virtual cubes.
  SphereVerdict check_ica(const Cube& c, const Box& box, const Vec3& d) const {
    const bool stored = c.node != Cube::kVirtual;
    const Vec3 w = (stored ? tree.node_centre(c.node) : Vec3((box.min + box.max) / 2)) - pivot;
    const double x = w.dot(d);
    const bool memo = stored && c.node < memo_end && use_cone[c.node];
    if (memo) {
      const double u = x / w.norm();
      const NodeCone& k = cone[c.node];
      if (k.hit.contains(u)) return SphereVerdict::hit;
      if (!k.reach.contains(u)) return SphereVerdict::miss;
    }
    const Vec3 radial = w - x * d;
    const double y2 = radial.squaredNorm();
    if (!memo) {
      const SphereVerdict v = detail::sphere_verdict(tool, x, y2, in2[c.level], out2[c.level]);
      if (v != SphereVerdict::corner) return v;
    }
    const double y = std::sqrt(y2);
    const Vec3 size = stored ? Vec3::Constant(tree.edge(c.level)) : Vec3(box.max - box.min);
    return detail::refine_corner(tool, size, d, radial, x, y, c.full != 0);
  }
};

class Traversal {
 public:
  // d: the unit direction of the sphere tests; raw: the direction as the sphere grid gives it,
  // which CheckBox normalises with a certified error.
  Traversal(const Prepared& p, const Vec3& d, const Vec3& raw) : p_(p), d_(d), raw_(raw) {
    // Children are pushed so that the octant nearest the pivot along d is tested first: a
    // colliding direction usually meets the part there.
    // Octant o lies at (sum over axes of +-|d_k|) along d from the parent's centre: the nearest
    // one, `base`, has bit k set where d_k < 0; flipping bits moves away by 2 |d_k| each. With
    // the axes sorted by |d_k| (s1 smallest), the order of the flip sets is fixed but for
    // {s1, s2} against {s3}. order_ runs from the farthest octant to the nearest (pushed in
    // that order, the nearest is tested first).
    const int base = (d.x() < 0) | (d.y() < 0) << 1 | (d.z() < 0) << 2;
    int axis[3] = {0, 1, 2};
    const double m[3] = {std::abs(d.x()), std::abs(d.y()), std::abs(d.z())};
    if (m[axis[1]] < m[axis[0]]) std::swap(axis[0], axis[1]);
    if (m[axis[2]] < m[axis[1]]) std::swap(axis[1], axis[2]);
    if (m[axis[1]] < m[axis[0]]) std::swap(axis[0], axis[1]);
    const int s1 = 1 << axis[0], s2 = 1 << axis[1], s3 = 1 << axis[2];
    const bool pair_first = m[axis[0]] + m[axis[1]] <= m[axis[2]];
    const int near_to_far[8] = {0, s1, s2, pair_first ? s1 | s2 : s3, pair_first ? s3 : s1 | s2, s1 | s3, s2 | s3, 7};
    for (int k = 0; k < 8; ++k) order_[k] = base ^ near_to_far[7 - k];
  }

  // `witness`: a full cube the previous direction of the same row collided with, or none
  // (full == 0); tested first, since neighbouring directions usually hit the same part of the
  // part; replaced by this direction's witness.
  bool collides(Counters& n, Cube& witness, Box& witness_box) {
    if (p_.tree.nodes().empty() || p_.tool.empty()) return false;
    if (witness.full) {
      ++n.node_tests;
      const bool hit = p_.method == AmMethod::checkbox ? box(witness_box, n) : p_.check_ica(witness, witness_box, d_) == SphereVerdict::hit;
      if (hit) return true;
    }
    witness.full = 0;
    push_node(0);
    while (top_ > 0) {
      --top_;
      const Cube c = stack_[top_];
      const Box b = c.node == Cube::kVirtual ? boxes_[top_] : Box{};
      const auto box_of = [&] { return c.node == Cube::kVirtual ? b : p_.tree.node_box(c.node); };
      const auto found = [&] {
        witness = c;
        witness_box = box_of();
        return true;
      };
      ++n.node_tests;
      if (p_.method == AmMethod::checkbox) {
        if (!box(box_of(), n)) continue;
        if (c.full) return found();
        push_children(c);
        continue;
      }
      const SphereVerdict v = p_.check_ica(c, b, d_);
      if (v == SphereVerdict::miss) continue;
      if (v == SphereVerdict::hit) {
        if (c.full) return found();
        push_children(c);
        continue;
      }
      // Corner case: ICA asks CheckBox; AICA opens the cube (full ones into octants) until the
      // last level, where CheckBox decides.
      if (p_.method == AmMethod::ica || (c.full && c.level >= p_.last_level)) {
        if (!box(box_of(), n)) continue;
        if (c.full) return found();
        push_children(c);
      } else if (c.full) {
        push_octants(c, box_of());
      } else {
        push_children(c);
      }
    }
    return false;
  }

 private:
  bool box(const Box& b, Counters& n) {
    if (!box_test_) box_test_.emplace(p_.pivot, raw_, p_.tool);
    ++n.checkbox_calls;
    const BoxVerdict v = (*box_test_)(b);
    n.quad += v.precision == Precision::quad_precision;
    n.undecided += v.precision == Precision::undecided;
    return v.collision;
  }
  void push_node(std::uint32_t i) {
    const OctreeNode& o = p_.tree.nodes()[i];
    stack_[top_++] = {i, o.level, o.full};
  }
  void push_children(const Cube& c) {
    const OctreeNode& o = p_.tree.nodes()[c.node];
    for (int k = 0; k < 8; ++k) {
      const int oct = order_[k];
      if (!(o.child_mask >> oct & 1)) continue;
      push_node(o.first_child + kBitCount[o.child_mask & ((1u << oct) - 1)]);
    }
  }
  void push_octants(const Cube& c, const Box& parent) {
    const Vec3 mid = (parent.min + parent.max) / 2;
    for (int k = 0; k < 8; ++k) {
      const int oct = order_[k];
      Box& o = boxes_[top_];
      o = parent;
      for (int a = 0; a < 3; ++a) (oct >> a & 1 ? o.min[a] : o.max[a]) = mid[a];
      stack_[top_++] = {Cube::kVirtual, std::uint8_t(c.level + 1), 1};
    }
  }

  const Prepared& p_;
  Vec3 d_, raw_;
  std::optional<CheckBox> box_test_;  // built at the first corner case
  int order_[8];
  // Depth-first: at most 8 pending cubes per level.
  std::array<Cube, 8 * 24> stack_;
  std::array<Box, 8 * 24> boxes_;  // of the virtual cubes on the stack
  int top_ = 0;
};

void validate(const Tool& tool) {
  if (tool.empty()) throw std::invalid_argument("access map: the tool has no cylinder");
  for (const ToolCylinder& c : tool)
    if (!std::isfinite(c.a) || !std::isfinite(c.b) || !std::isfinite(c.r) || c.b < c.a || c.r < 0)
      throw std::invalid_argument("access map: a tool cylinder needs finite a <= b and r >= 0");
}

}  // namespace

AmMethod parse_am_method(const std::string& name) {
  if (name == "checkbox") return AmMethod::checkbox;
  if (name == "ica") return AmMethod::ica;
  if (name == "aica") return AmMethod::aica;
  throw std::invalid_argument("unknown access-map method '" + name + "' (aica, ica or checkbox)");
}

std::string to_string(AmMethod m) {
  switch (m) {
    case AmMethod::checkbox: return "checkbox";
    case AmMethod::ica: return "ica";
    case AmMethod::aica: return "aica";
  }
  return "?";
}

long AccessMap::collisions() const {
  long n = 0;
  for (auto c : cells) n += c;
  return n;
}

std::vector<std::string> AccessMap::rows() const {
  std::vector<std::string> out(std::size_t(sphere.rows), std::string(std::size_t(sphere.cols), '0'));
  for (int i = 0; i < sphere.rows; ++i)
    for (int j = 0; j < sphere.cols; ++j)
      if (collides(i, j)) out[std::size_t(i)][std::size_t(j)] = '1';
  return out;
}

AccessMap compute_access_map(const Octree& tree, const Vec3& pivot, const Tool& tool, const SphereGrid& sphere,
                             const AmOptions& options) {
  validate(tool);
  if (!pivot.allFinite()) throw std::invalid_argument("access map: the pivot is not finite");
  if (sphere.rows < 1 || sphere.cols < 1) throw std::invalid_argument("access map: the sphere grid needs rows, cols >= 1");
  if (tree.touches_solid(pivot)) throw std::invalid_argument("access map: the pivot lies inside the part (in a solid voxel)");
  // One thread runs on the caller without an arena.
  tbb::task_arena arena(options.threads > 1 ? options.threads : tbb::task_arena::automatic);

  const auto& nodes = tree.nodes();
  // Cylinders starting beyond the farthest corner of the octree's root cannot touch a voxel:
  // every method leaves them out (a holder far from the part costs nothing).
  Tool reach;
  if (!nodes.empty()) {
    const Box root = tree.node_box(0);
    double far = 0;
    for (int k = 0; k < 8; ++k)
      far = std::max(far, (Vec3(k & 1 ? root.max.x() : root.min.x(), k & 2 ? root.max.y() : root.min.y(), k & 4 ? root.max.z() : root.min.z()) - pivot).norm());
    for (const ToolCylinder& c : tool)
      if (c.a <= far * (1 + 1e-12) + detail::kSphereMargin) reach.push_back(c);
  }
  Prepared p{tree, reach, pivot, options.method, 0, {}, {}, 0, {}, {}};
  p.last_level = tree.depth() + std::clamp(options.subvoxel_levels, 0, 6);
  for (int level = 0; level <= p.last_level; ++level) {
    const double edge = std::ldexp(tree.spec().voxel_size, tree.depth() - level);
    const double in = edge / 2 - detail::kSphereMargin, out = edge * std::sqrt(3.0) / 2 + detail::kSphereMargin;
    p.in2.push_back(in > 0 ? in * in : -1.0);
    p.out2.push_back(out * out);
  }
  if (options.method != AmMethod::checkbox && options.memo_levels > 0 && !nodes.empty()) {
    p.memo_end = tree.level_end(std::min(options.memo_levels, tree.depth() + 1) - 1);
    p.cone.resize(p.memo_end);
    p.use_cone.assign(p.memo_end, 0);
    const auto memoise = [&](std::uint32_t i) {
      const double edge = tree.edge(nodes[i].level), rho_out = edge * std::sqrt(3.0) / 2;
      const double distance = (tree.node_centre(i) - pivot).norm();
      // Near the pivot the cone reading of u loses accuracy: test those nodes directly.
      if (distance <= 2 * rho_out) return;
      p.cone[i] = detail::node_cone(reach, distance, edge / 2, rho_out);
      p.use_cone[i] = 1;
    };
    if (options.threads == 1) {
      for (std::uint32_t i = 0; i < p.memo_end; ++i) memoise(i);
    } else {
      arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<std::uint32_t>(0, p.memo_end, 16), [&](const auto& range) {
          for (std::uint32_t i = range.begin(); i != range.end(); ++i) memoise(i);
        });
      });
    }
  }

  AccessMap map{sphere, std::vector<std::uint8_t>(std::size_t(sphere.rows) * std::size_t(sphere.cols), 0), {}};
  std::vector<Counters> counters(map.cells.size());
  // One task per row, its columns in order: the witness passed along a row makes the counters,
  // too, independent of the thread count.
  // The sphere grid's directions, with SphereGrid::direction's arithmetic, from one sine and
  // cosine per row and per column.
  std::vector<double> sin_gamma(std::size_t(sphere.cols)), cos_gamma(std::size_t(sphere.cols));
  for (int j = 0; j < sphere.cols; ++j) {
    const double gamma = (j + 0.5) * 2 * M_PI / sphere.cols;
    sin_gamma[std::size_t(j)] = std::sin(gamma);
    cos_gamma[std::size_t(j)] = std::cos(gamma);
  }
  const auto row = [&](int i) {
    const double phi = (i + 0.5) * M_PI / sphere.rows, sin_phi = std::sin(phi), cos_phi = std::cos(phi);
    Cube witness{};
    Box witness_box;
    for (int j = 0; j < sphere.cols; ++j) {
      const std::size_t cell = std::size_t(i) * std::size_t(sphere.cols) + std::size_t(j);
      const Vec3 raw(sin_phi * cos_gamma[std::size_t(j)], sin_phi * sin_gamma[std::size_t(j)], cos_phi);
      Traversal t(p, raw.normalized(), raw);
      map.cells[cell] = t.collides(counters[cell], witness, witness_box);
    }
  };
  if (options.threads == 1) {
    for (int i = 0; i < sphere.rows; ++i) row(i);
  } else {
    arena.execute([&] {
      tbb::parallel_for(tbb::blocked_range<int>(0, sphere.rows, 1), [&](const auto& range) {
        for (int i = range.begin(); i != range.end(); ++i) row(i);
      });
    });
  }
  for (const Counters& c : counters) {
    map.stats.node_tests += c.node_tests;
    map.stats.checkbox_calls += c.checkbox_calls;
    map.stats.quad_verdicts += c.quad;
    map.stats.undecided += c.undecided;
  }
  map.stats.memo_nodes = p.memo_end;
  return map;
}

}  // namespace mtcs::voxel
