// The per-direction octree traversal of every method, the per-map preparation (node centres
// relative to the pivot, memoised cone intervals) and the parallel loop over directions.

#include "mtcs/voxel/accessibility_map.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <array>
#include <cmath>
#include <stdexcept>

#include "mtcs/voxel/check_box.h"
#include "ica.h"

namespace mtcs::voxel {
namespace {

using detail::NodeCone;
using detail::SphereVerdict;

// A cube on the traversal stack: a stored node, or an octant of a full node (node = kVirtual).
struct Cube {
  static constexpr std::uint32_t kVirtual = 0xffffffffu;
  std::uint32_t node;
  std::array<std::uint16_t, 3> corner;
  std::uint8_t level;
  std::uint8_t full;
};

struct Counters {
  std::uint64_t node_tests = 0, checkbox_calls = 0, quad = 0, undecided = 0;
};

// Everything about the octree that does not depend on the direction.
struct Prepared {
  const Octree& tree;
  const Tool& tool;
  Vec3 pivot;
  AmMethod method;
  std::vector<Vec3> offset;          // node centre - pivot
  std::vector<double> distance;      // |offset|
  std::vector<NodeCone> cone;        // for nodes [0, memo_end)
  std::vector<char> use_cone;        // cone valid (centre not too near the pivot)
  std::uint32_t memo_end = 0;
  std::vector<double> in2, out2;     // per level: squared test radii of the spheres

  SphereVerdict direct(const Vec3& w, const Vec3& d, int level) const {
    const double x = w.dot(d), y = (w - x * d).norm();
    return detail::sphere_verdict(tool, x, y, in2[std::size_t(level)], out2[std::size_t(level)]);
  }

  SphereVerdict check_ica(const Cube& c, const Vec3& d) const {
    if (c.node != Cube::kVirtual && c.node < memo_end && use_cone[c.node]) {
      const double u = offset[c.node].dot(d) / distance[c.node];
      const NodeCone& k = cone[c.node];
      if (k.hit.contains(u)) return SphereVerdict::hit;
      if (!k.reach.contains(u)) return SphereVerdict::miss;
      return SphereVerdict::corner;
    }
    const Vec3 w = c.node != Cube::kVirtual ? offset[c.node] : tree.centre(c.corner, c.level) - pivot;
    return direct(w, d, c.level);
  }
};

class Traversal {
 public:
  // d: the unit direction of the sphere tests; raw: the direction as the sphere grid gives it,
  // which CheckBox normalises with a certified error.
  Traversal(const Prepared& p, const Vec3& d, const Vec3& raw) : p_(p), d_(d), box_test_(p.pivot, raw, p.tool) {}

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
      // Corner case.
      if (p_.method == AmMethod::ica || (c.full && c.level == p_.tree.depth())) {
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
    ++n.checkbox_calls;
    const BoxVerdict v = box_test_(p_.tree.box(c.corner, c.level));
    n.quad += v.precision == Precision::quad_precision;
    n.undecided += v.precision == Precision::undecided;
    return v.collision;
  }
  void push_node(std::uint32_t i) {
    const OctreeNode& o = p_.tree.nodes()[i];
    stack_[top_++] = {i, o.corner, o.level, o.full};
  }
  void push_children(const Cube& c) {
    const OctreeNode& o = p_.tree.nodes()[c.node];
    for (std::uint32_t k = 0; k < o.child_count; ++k) push_node(o.first_child + k);
  }
  void push_octants(const Cube& c) {
    const int w = p_.tree.voxels_across(c.level + 1);
    for (int k = 0; k < 8; ++k) {
      Cube o{Cube::kVirtual, c.corner, std::uint8_t(c.level + 1), 1};
      for (int a = 0; a < 3; ++a) o.corner[std::size_t(a)] = std::uint16_t(o.corner[std::size_t(a)] + ((k >> a) & 1) * w);
      stack_[top_++] = o;
    }
  }

  const Prepared& p_;
  Vec3 d_;
  CheckBox box_test_;
  // Depth-first: at most 8 pending cubes per level.
  std::array<Cube, 8 * 17> stack_;
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

  Prepared p{tree, tool, pivot, options.method, {}, {}, {}, {}, 0, {}, {}};
  const auto& nodes = tree.nodes();
  p.offset.resize(nodes.size());
  p.distance.resize(nodes.size());
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    p.offset[i] = tree.centre(nodes[i]) - pivot;
    p.distance[i] = p.offset[i].norm();
  }
  for (int level = 0; level <= tree.depth(); ++level) {
    const double in = tree.edge(level) / 2 - detail::kSphereMargin, out = tree.edge(level) * std::sqrt(3.0) / 2 + detail::kSphereMargin;
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
          // Near the pivot the cone reading of u loses accuracy: test those nodes directly.
          if (p.distance[i] <= 2 * rho_out) continue;
          p.cone[i] = detail::node_cone(tool, p.distance[i], edge / 2, rho_out);
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
