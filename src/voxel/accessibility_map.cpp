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

#include "mtcs/voxel/check_box.h"
#include "ica.h"

namespace mtcs::voxel {
namespace {

using detail::NodeCone;
using detail::SphereVerdict;

// A cube on the traversal stack: a stored node, or an octant of a full node or of a voxel
// (node = kVirtual), kept as its closed box (octants split at the midpoint, so they cover
// their parent exactly).
struct Cube {
  static constexpr std::uint32_t kVirtual = 0xffffffffu;
  Box box;
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

  SphereVerdict check_ica(const Cube& c, const Vec3& d) const {
    const Vec3 w = (c.node != Cube::kVirtual ? tree.node_centre(c.node) : Vec3((c.box.min + c.box.max) / 2)) - pivot;
    const double x = w.dot(d);
    SphereVerdict v;
    if (c.node < memo_end && use_cone[c.node]) {
      const double u = x / w.norm();
      const NodeCone& k = cone[c.node];
      v = k.hit.contains(u) ? SphereVerdict::hit : (k.reach.contains(u) ? SphereVerdict::corner : SphereVerdict::miss);
      if (v != SphereVerdict::corner) return v;
    }
    const Vec3 radial = w - x * d;
    const double y = radial.norm();
    if (!(c.node < memo_end && use_cone[c.node])) {
      v = detail::sphere_verdict(tool, x, y, in2[c.level], out2[c.level]);
      if (v != SphereVerdict::corner) return v;
    }
    return detail::refine_corner(tool, c.box.max - c.box.min, d, radial, x, y, c.full != 0);
  }
};

class Traversal {
 public:
  // d: the unit direction of the sphere tests; raw: the direction as the sphere grid gives it,
  // which CheckBox normalises with a certified error.
  Traversal(const Prepared& p, const Vec3& d, const Vec3& raw) : p_(p), d_(d), raw_(raw) {
    // Children are pushed so that the octant nearest the pivot along d is tested first: a
    // colliding direction usually meets the part there.
    for (int o = 0; o < 8; ++o) order_[o] = o;
    double key[8];
    for (int o = 0; o < 8; ++o) key[o] = ((o & 1) ? d.x() : -d.x()) + ((o & 2) ? d.y() : -d.y()) + ((o & 4) ? d.z() : -d.z());
    std::sort(order_, order_ + 8, [&](int a, int b) { return key[a] > key[b]; });
  }

  bool collides(Counters& n) {
    if (p_.tree.nodes().empty()) return false;
    push_node(0);
    while (top_ > 0) {
      const Cube c = stack_[--top_];
      ++n.node_tests;
      if (p_.method == AmMethod::checkbox) {
        if (!box(c, n)) continue;
        if (c.full) return true;
        push_children(c);
        continue;
      }
      const SphereVerdict v = p_.check_ica(c, d_);
      if (v == SphereVerdict::miss) continue;
      if (v == SphereVerdict::hit) {
        if (c.full) return true;
        push_children(c);
        continue;
      }
      // Corner case: ICA asks CheckBox; AICA opens the cube (full ones into octants) until the
      // last level, where CheckBox decides.
      if (p_.method == AmMethod::ica || (c.full && c.level >= p_.last_level)) {
        if (!box(c, n)) continue;
        if (c.full) return true;
        push_children(c);
      } else if (c.full) {
        push_octants(c);
      } else {
        push_children(c);
      }
    }
    return false;
  }

 private:
  bool box(const Cube& c, Counters& n) {
    if (!box_test_) box_test_.emplace(p_.pivot, raw_, p_.tool);
    ++n.checkbox_calls;
    const BoxVerdict v = (*box_test_)(c.box);
    n.quad += v.precision == Precision::quad_precision;
    n.undecided += v.precision == Precision::undecided;
    return v.collision;
  }
  void push_node(std::uint32_t i) {
    const OctreeNode& o = p_.tree.nodes()[i];
    stack_[top_++] = {p_.tree.node_box(i), i, o.level, o.full};
  }
  void push_children(const Cube& c) {
    const OctreeNode& o = p_.tree.nodes()[c.node];
    for (int k = 0; k < 8; ++k) {
      const int oct = order_[k];
      if (!(o.child_mask >> oct & 1)) continue;
      push_node(o.first_child + kBitCount[o.child_mask & ((1u << oct) - 1)]);
    }
  }
  void push_octants(const Cube& c) {
    const Vec3 mid = (c.box.min + c.box.max) / 2;
    for (int k = 0; k < 8; ++k) {
      const int oct = order_[k];
      Cube o{c.box, Cube::kVirtual, std::uint8_t(c.level + 1), 1};
      for (int a = 0; a < 3; ++a) (oct >> a & 1 ? o.box.min[a] : o.box.max[a]) = mid[a];
      stack_[top_++] = o;
    }
  }

  const Prepared& p_;
  Vec3 d_, raw_;
  std::optional<CheckBox> box_test_;  // built at the first corner case
  int order_[8];
  // Depth-first: at most 8 pending cubes per level.
  std::array<Cube, 8 * 24> stack_;
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
  tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);

  Prepared p{tree, tool, pivot, options.method, 0, {}, {}, 0, {}, {}};
  const auto& nodes = tree.nodes();
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
    arena.execute([&] {
      tbb::parallel_for(tbb::blocked_range<std::uint32_t>(0, p.memo_end, 16), [&](const auto& range) {
        for (std::uint32_t i = range.begin(); i != range.end(); ++i) {
          const double edge = tree.edge(nodes[i].level), rho_out = edge * std::sqrt(3.0) / 2;
          const double distance = (tree.node_centre(i) - pivot).norm();
          // Near the pivot the cone reading of u loses accuracy: test those nodes directly.
          if (distance <= 2 * rho_out) continue;
          p.cone[i] = detail::node_cone(tool, distance, edge / 2, rho_out);
          p.use_cone[i] = 1;
        }
      });
    });
  }

  AccessMap map{sphere, std::vector<std::uint8_t>(std::size_t(sphere.rows) * std::size_t(sphere.cols), 0), {}};
  std::vector<Counters> counters(map.cells.size());
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<int>(0, int(map.cells.size()), 4), [&](const auto& range) {
      for (int cell = range.begin(); cell != range.end(); ++cell) {
        const Vec3 raw = sphere.direction(cell / sphere.cols, cell % sphere.cols);
        Traversal t(p, raw.normalized(), raw);
        map.cells[std::size_t(cell)] = t.collides(counters[std::size_t(cell)]);
      }
    });
  });
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
