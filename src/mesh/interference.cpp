#include "mtcs/mesh/interference.h"

#include "ray_parity.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>

#include <Eigen/Dense>

#include "mtcs/mesh/exact_predicates.h"

namespace mtcs::mesh {
namespace {

constexpr int kLeafSize = 4;  // at most 32: leaves' triangles are tracked as bit masks

Box box_of(const Triangle& t) { return {t[0].cwiseMin(t[1]).cwiseMin(t[2]), t[0].cwiseMax(t[1]).cwiseMax(t[2])}; }

// Closed boxes: touching boxes overlap, so touching triangles are never pruned.
bool overlap(const Box& a, const Box& b) {
  return (a.min.array() <= b.max.array()).all() && (b.min.array() <= a.max.array()).all();
}

double extent(const Box& b) { return (b.max - b.min).sum(); }


// A cheap, conservative filter: false only when the triangle's box misses the box, or the box
// lies strictly on one side of the triangle's plane by more than a rounding margin (the exact
// test decides everything else).
bool triangle_may_meet_box(const Triangle& t, const Box& tbox, const Vec3& n, const Box& box) {
  if (!overlap(tbox, box)) return false;
  const Vec3 c = (box.min + box.max) / 2, h = (box.max - box.min) / 2;
  const double reach = n.cwiseAbs().dot(h), offset = n.dot(c - t[0]);
  const double margin = 1e-12 * n.cwiseAbs().sum() * (c.cwiseAbs().maxCoeff() + h.maxCoeff() + t[0].cwiseAbs().maxCoeff());
  return std::abs(offset) <= reach + margin;
}

// Lower bounds on the distance from triangle t (normal n) to a point set: how far the set lies
// beyond the plane of t, or beyond one of the three planes through an edge of t perpendicular
// to t (t lies wholly on the inner side of each). Far from t's own size, the edge planes are
// what separates a small part hovering over a hole in a large fanned face. Up to rounding:
// callers prune at bound >= (1 - slack) best.
template <class Reach>  // reach(unit m, origin): the least m . (x - origin) over the set
double prism_gap(const Triangle& t, const Vec3& n, Reach&& reach) {
  const Vec3 u = n / n.norm();
  double gap = std::max(reach(u, t[0]), reach(Vec3(-u), t[0]));
  for (int k = 0; k < 3; ++k) {
    const Vec3& e0 = t[k];
    const Vec3 m = (t[(k + 1) % 3] - e0).cross(u);  // outward in t's plane (t counter-clockwise about n)
    gap = std::max(gap, reach(Vec3(m / m.norm()), e0));
  }
  return std::max(gap, 0.0);
}

double triangle_gap(const Triangle& t, const Vec3& n, const Triangle& other) {
  return prism_gap(t, n, [&](const Vec3& m, const Vec3& o) {
    return std::min({m.dot(other[0] - o), m.dot(other[1] - o), m.dot(other[2] - o)});
  });
}

double triangle_box_gap(const Triangle& t, const Vec3& n, const Box& box) {
  const Vec3 c = (box.min + box.max) / 2, h = (box.max - box.min) / 2;
  return prism_gap(t, n, [&](const Vec3& m, const Vec3& o) { return m.dot(c - o) - m.cwiseAbs().dot(h); });
}

bool share_corner(const std::array<int, 3>& a, const std::array<int, 3>& b) {
  for (int i : a)
    for (int j : b)
      if (i == j) return true;
  return false;
}

}  // namespace

InterferenceBvh::InterferenceBvh(const TriangleMesh& mesh, MeshParts parts, Split split) : parts_(std::move(parts)) {
  const std::size_t n = mesh.triangles.size();
  tris_.resize(n);
  for (std::size_t t = 0; t < n; ++t) tris_[t] = {mesh.corner(t, 0), mesh.corner(t, 1), mesh.corner(t, 2)};
  order_.resize(n);
  std::iota(order_.begin(), order_.end(), 0);
  if (split == Split::kSolidFace)  // whole solids and faces must start out contiguous
    std::stable_sort(order_.begin(), order_.end(), [&](int x, int y) {
      return std::pair(parts_.solid_of[x], parts_.face_of[x]) < std::pair(parts_.solid_of[y], parts_.face_of[y]);
    });
  std::vector<Vec3> centroids(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Triangle& t = tris_[std::size_t(order_[i])];
    centroids[i] = (t[0] + t[1] + t[2]) / 3;
  }
  nodes_.reserve(2 * n / kLeafSize + 2);
  nodes_.resize(1);
  if (n > 0) build(0, 0, int(n), split, centroids);
  std::vector<Triangle> by_position(n);
  ids_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    by_position[i] = tris_[std::size_t(order_[i])];
    ids_[i] = mesh.triangles[std::size_t(order_[i])];
  }
  tris_ = std::move(by_position);
  for (const Triangle& t : tris_) boxes_.push_back(box_of(t)), normals_.push_back((t[1] - t[0]).cross(t[2] - t[0]));
}

void InterferenceBvh::build(int node, int begin, int end, Split split, std::vector<Vec3>& centroids) {
  Box box = Box::empty();
  for (int i = begin; i < end; ++i) {
    const Box b = box_of(tris_[std::size_t(order_[i])]);
    box.min = box.min.cwiseMin(b.min), box.max = box.max.cwiseMax(b.max);
  }
  nodes_[node] = {box, -1, begin, end};
  if (end - begin <= kLeafSize) return;
  int mid = -1;
  if (split == Split::kSolidFace) {
    mid = split_groups(begin, end, parts_.solid_of, centroids);
    if (mid < 0) mid = split_groups(begin, end, parts_.face_of, centroids);
  }
  if (mid < 0) mid = split_median(begin, end, centroids);
  const int left = int(nodes_.size());
  nodes_.resize(nodes_.size() + 2);
  nodes_[node].child = left;
  build(left, begin, mid, split, centroids);
  build(left + 1, mid, end, split, centroids);
}

// Splits [begin, end) between whole groups (runs of equal key), ordered by their centroids along
// the longest axis, about half the triangles each side; -1 when the range holds one group.
int InterferenceBvh::split_groups(int begin, int end, const std::vector<int>& key, std::vector<Vec3>& centroids) {
  struct Run {
    int start, count;
    Vec3 centroid;
  };
  std::vector<Run> runs;
  for (int i = begin; i < end; ++i) {
    if (runs.empty() || key[std::size_t(order_[i])] != key[std::size_t(order_[runs.back().start])])
      runs.push_back({i, 0, Vec3::Zero()});
    ++runs.back().count;
    runs.back().centroid += centroids[i];
  }
  if (runs.size() < 2) return -1;
  Box cbox = Box::empty();
  for (Run& r : runs) {
    r.centroid /= r.count;
    cbox.min = cbox.min.cwiseMin(r.centroid), cbox.max = cbox.max.cwiseMax(r.centroid);
  }
  int axis = 0;
  (cbox.max - cbox.min).maxCoeff(&axis);
  std::sort(runs.begin(), runs.end(), [axis](const Run& x, const Run& y) { return x.centroid[axis] < y.centroid[axis]; });
  std::vector<int> order;
  std::vector<Vec3> cents;
  order.reserve(std::size_t(end - begin)), cents.reserve(std::size_t(end - begin));
  int mid = -1;
  for (std::size_t r = 0; r < runs.size(); ++r) {
    if (mid < 0 && r > 0 && (2 * int(order.size()) >= end - begin || r + 1 == runs.size())) mid = begin + int(order.size());
    for (int i = runs[r].start; i < runs[r].start + runs[r].count; ++i) order.push_back(order_[i]), cents.push_back(centroids[i]);
  }
  std::copy(order.begin(), order.end(), order_.begin() + begin);
  std::copy(cents.begin(), cents.end(), centroids.begin() + begin);
  return mid;
}

int InterferenceBvh::split_median(int begin, int end, std::vector<Vec3>& centroids) {
  Box cbox = Box::empty();
  for (int i = begin; i < end; ++i) cbox.min = cbox.min.cwiseMin(centroids[i]), cbox.max = cbox.max.cwiseMax(centroids[i]);
  int axis = 0;
  (cbox.max - cbox.min).maxCoeff(&axis);
  std::vector<int> idx(std::size_t(end - begin));
  std::iota(idx.begin(), idx.end(), begin);
  const int half = (end - begin) / 2;
  std::nth_element(idx.begin(), idx.begin() + half, idx.end(),
                   [&](int x, int y) { return centroids[x][axis] < centroids[y][axis]; });
  std::vector<int> order(idx.size());
  std::vector<Vec3> cents(idx.size());
  for (std::size_t i = 0; i < idx.size(); ++i) order[i] = order_[idx[i]], cents[i] = centroids[idx[i]];
  std::copy(order.begin(), order.end(), order_.begin() + begin);
  std::copy(cents.begin(), cents.end(), centroids.begin() + begin);
  return begin + half;
}

bool InterferenceBvh::contains(const Vec3& p) const {
  if (tris_.empty() || !nodes_[0].box.contains(p)) return false;
  return detail::inside_by_parity(p, [this](const Vec3& o, const Vec3& d, auto&& on_triangle) {
    const Vec3 inv = d.cwiseInverse();
    std::vector<int> stack{0};
    while (!stack.empty()) {
      const Node& node = nodes_[std::size_t(stack.back())];
      stack.pop_back();
      if (!detail::ray_meets_box(o, inv, node.box)) continue;
      if (node.child < 0) {
        for (int i = node.begin; i < node.end; ++i) on_triangle(tris_[std::size_t(i)]);
        continue;
      }
      stack.push_back(node.child), stack.push_back(node.child + 1);
    }
  });
}

std::vector<InterferencePair> intersecting_pairs(const InterferenceBvh& a, const InterferenceBvh& b,
                                                 InterferenceStats* stats) {
  std::vector<InterferencePair> pairs;
  InterferenceStats local;
  if (a.size() == 0 || b.size() == 0) return pairs;
  const auto& na = a.nodes();
  const auto& nb = b.nodes();
  // A leaf's triangles that may still meet the other side's subtree, as a bit mask: once a
  // triangle is culled against a node's box it stays culled below that node. This keeps long,
  // thin CAD triangles (whose own boxes are large) from being tested against every leaf of a
  // small part.
  struct Entry {
    int i, j;
    unsigned ma, mb;
  };
  auto cull = [](const InterferenceBvh& t, const InterferenceBvh::Node& leaf, unsigned mask, const Box& other) {
    mask &= (1u << (leaf.end - leaf.begin)) - 1;  // leaves may hold fewer than kLeafSize
    for (int p = leaf.begin; p < leaf.end; ++p)
      if ((mask >> (p - leaf.begin) & 1u) && !triangle_may_meet_box(t.triangle(p), t.triangle_box(p), t.normal(p), other)) mask &= ~(1u << (p - leaf.begin));
    return mask;
  };
  std::vector<Entry> stack{{0, 0, ~0u, ~0u}};
  while (!stack.empty()) {
    Entry e = stack.back();
    stack.pop_back();
    ++local.node_pairs;
    const auto& x = na[std::size_t(e.i)];
    const auto& y = nb[std::size_t(e.j)];
    if (!overlap(x.box, y.box)) continue;
    if (x.child < 0 && (e.ma = cull(a, x, e.ma, y.box)) == 0) continue;
    if (y.child < 0 && (e.mb = cull(b, y, e.mb, x.box)) == 0) continue;
    if (x.child < 0 && y.child < 0) {
      for (int p = x.begin; p < x.end; ++p) {
        if (!(e.ma >> (p - x.begin) & 1u)) continue;
        const Triangle& ta = a.triangle(p);
        const Box& ba = a.triangle_box(p);
        for (int q = y.begin; q < y.end; ++q) {
          if (!(e.mb >> (q - y.begin) & 1u)) continue;
          const Triangle& tb = b.triangle(q);
          if (!overlap(ba, b.triangle_box(q))) continue;
          ++local.triangle_tests;
          const TriangleIntersection hit = intersect_triangles(ta, tb);
          if (hit.intersects) pairs.push_back({a.triangle_at(p), b.triangle_at(q), hit});
        }
      }
    } else if (y.child < 0 || (x.child >= 0 && extent(x.box) >= extent(y.box))) {
      stack.push_back({x.child, e.j, e.ma, e.mb}), stack.push_back({x.child + 1, e.j, e.ma, e.mb});
    } else {
      stack.push_back({e.i, y.child, e.ma, e.mb}), stack.push_back({e.i, y.child + 1, e.ma, e.mb});
    }
  }
  std::sort(pairs.begin(), pairs.end(), [](const auto& p, const auto& q) { return std::pair(p.a, p.b) < std::pair(q.a, q.b); });
  if (stats) *stats = local;
  return pairs;
}

std::vector<std::array<int, 2>> self_intersections(const InterferenceBvh& bvh, InterferenceStats* stats) {
  std::vector<std::array<int, 2>> found;
  InterferenceStats local;
  if (bvh.size() == 0) return found;
  const auto& nodes = bvh.nodes();
  auto test = [&](int p, int q) {
    if (share_corner(bvh.corners(p), bvh.corners(q))) return;
    if (!overlap(bvh.triangle_box(p), bvh.triangle_box(q))) return;
    ++local.triangle_tests;
    if (triangles_intersect(bvh.triangle(p), bvh.triangle(q)))
      found.push_back({std::min(bvh.triangle_at(p), bvh.triangle_at(q)), std::max(bvh.triangle_at(p), bvh.triangle_at(q))});
  };
  std::vector<std::pair<int, int>> stack{{0, 0}};
  while (!stack.empty()) {
    const auto [i, j] = stack.back();
    stack.pop_back();
    ++local.node_pairs;
    const auto& x = nodes[std::size_t(i)];
    const auto& y = nodes[std::size_t(j)];
    if (i == j) {  // a node against itself: its children against themselves and each other
      if (x.child < 0) {
        for (int p = x.begin; p < x.end; ++p)
          for (int q = p + 1; q < x.end; ++q) test(p, q);
      } else {
        stack.push_back({x.child, x.child}), stack.push_back({x.child + 1, x.child + 1}), stack.push_back({x.child, x.child + 1});
      }
      continue;
    }
    if (!overlap(x.box, y.box)) continue;
    if (x.child < 0 && y.child < 0) {
      for (int p = x.begin; p < x.end; ++p)
        for (int q = y.begin; q < y.end; ++q) test(p, q);
    } else if (y.child < 0 || (x.child >= 0 && extent(x.box) >= extent(y.box))) {
      stack.push_back({x.child, j}), stack.push_back({x.child + 1, j});
    } else {
      stack.push_back({i, y.child}), stack.push_back({i, y.child + 1});
    }
  }
  std::sort(found.begin(), found.end());
  if (stats) *stats = local;
  return found;
}

double surface_distance(const InterferenceBvh& a, const InterferenceBvh& b, InterferenceStats* stats) {
  // Pairs whose lower bound comes within this relative slack of the best distance are pruned:
  // parallel faces at the same gap (common in CAD) would otherwise all be visited; the answer
  // stays within 1e-12 relative (plus rounding) of the minimum.
  constexpr double kKeep = 1 - 1e-12;
  InterferenceStats local;
  double best = std::numeric_limits<double>::infinity();
  if (a.size() == 0 || b.size() == 0) return best;
  const auto& na = a.nodes();
  const auto& nb = b.nodes();
  // As in intersecting_pairs, per leaf a mask of the triangles that may still come nearer than
  // the best distance to the other subtree.
  struct Entry {
    int i, j;
    unsigned ma, mb;
  };
  auto cull = [&best, kKeep](const InterferenceBvh& t, const InterferenceBvh::Node& leaf, unsigned mask, const Box& other) {
    mask &= (1u << (leaf.end - leaf.begin)) - 1;
    for (int p = leaf.begin; p < leaf.end; ++p)
      if ((mask >> (p - leaf.begin) & 1u) &&
          (geometry::box_distance_sq(t.triangle_box(p), other) >= best * best || triangle_box_gap(t.triangle(p), t.normal(p), other) >= kKeep * best))
        mask &= ~(1u << (p - leaf.begin));
    return mask;
  };
  std::vector<Entry> stack{{0, 0, ~0u, ~0u}};
  while (!stack.empty() && best > 0) {
    Entry e = stack.back();
    stack.pop_back();
    ++local.node_pairs;
    const auto& x = na[std::size_t(e.i)];
    const auto& y = nb[std::size_t(e.j)];
    if (geometry::box_distance_sq(x.box, y.box) >= best * best) continue;
    if (x.child < 0 && (e.ma = cull(a, x, e.ma, y.box)) == 0) continue;
    if (y.child < 0 && (e.mb = cull(b, y, e.mb, x.box)) == 0) continue;
    if (x.child < 0 && y.child < 0) {
      for (int p = x.begin; p < x.end; ++p) {
        if (!(e.ma >> (p - x.begin) & 1u)) continue;
        for (int q = y.begin; q < y.end; ++q) {
          if (!(e.mb >> (q - y.begin) & 1u)) continue;
          if (geometry::box_distance_sq(a.triangle_box(p), b.triangle_box(q)) >= best * best) continue;
          if (triangle_gap(a.triangle(p), a.normal(p), b.triangle(q)) >= kKeep * best ||
              triangle_gap(b.triangle(q), b.normal(q), a.triangle(p)) >= kKeep * best)
            continue;
          ++local.triangle_tests;
          best = std::min(best, triangle_distance(a.triangle(p), b.triangle(q)));
        }
      }
      continue;
    }
    Entry c0 = e, c1 = e;
    if (y.child < 0 || (x.child >= 0 && extent(x.box) >= extent(y.box))) c0.i = x.child, c1.i = x.child + 1;
    else c0.j = y.child, c1.j = y.child + 1;
    // The nearer pair last, so that it is taken first and tightens the bound early. Near a
    // leaf with large triangles every box distance is 0: their planes tell the pairs apart.
    auto lower = [&](const Entry& c) {
      const Box& bx = na[std::size_t(c.i)].box;
      const Box& by = nb[std::size_t(c.j)].box;
      double d = std::sqrt(geometry::box_distance_sq(bx, by));
      if (y.child < 0) {
        double g = std::numeric_limits<double>::infinity();
        for (int q = y.begin; q < y.end; ++q)
          if (c.mb >> (q - y.begin) & 1u) g = std::min(g, triangle_box_gap(b.triangle(q), b.normal(q), bx));
        d = std::max(d, g);
      } else if (x.child < 0) {
        double g = std::numeric_limits<double>::infinity();
        for (int p = x.begin; p < x.end; ++p)
          if (c.ma >> (p - x.begin) & 1u) g = std::min(g, triangle_box_gap(a.triangle(p), a.normal(p), by));
        d = std::max(d, g);
      }
      return d;
    };
    if (lower(c0) < lower(c1)) stack.push_back(c1), stack.push_back(c0);
    else stack.push_back(c0), stack.push_back(c1);
  }
  if (stats) *stats = local;
  return std::max(best, 0.0);
}

TriangleMesh shrunk(const TriangleMesh& mesh, double offset) {
  // The distinct unit normals around each vertex.
  std::vector<std::vector<Vec3>> normals(mesh.vertices.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Vec3 n = (mesh.corner(t, 1) - mesh.corner(t, 0)).cross(mesh.corner(t, 2) - mesh.corner(t, 0)).normalized();
    for (int v : mesh.triangles[t]) {
      auto& ns = normals[std::size_t(v)];
      if (std::none_of(ns.begin(), ns.end(), [&](const Vec3& m) { return m.dot(n) > 1 - 1e-9; })) ns.push_back(n);
    }
  }
  TriangleMesh out = mesh;
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    const auto& ns = normals[v];
    if (ns.empty()) continue;
    Eigen::MatrixXd n(ns.size(), 3);
    for (std::size_t i = 0; i < ns.size(); ++i) n.row(Eigen::Index(i)) = ns[i].transpose();
    // Each incident plane moves by -offset along its normal: n d = -offset.
    Vec3 d = n.completeOrthogonalDecomposition().solve(Eigen::VectorXd::Constant(Eigen::Index(ns.size()), -offset));
    if (d.norm() > 3 * offset) d *= 3 * offset / d.norm();
    out.vertices[v] += d;
  }
  return out;
}

InterferenceReport interfere(const TriangleMesh& a, const TriangleMesh& b, double touch_tolerance,
                             InterferenceBvh::Split split) {
  InterferenceReport r;
  const InterferenceBvh ba(a, split_parts(a), split), bb(b, split_parts(b), split);
  r.pairs = intersecting_pairs(ba, bb, &r.stats);
  // What counts: the pairs and nesting of the shrunk solids (the meshes themselves without a
  // tolerance).
  std::vector<InterferencePair> deep_pairs;
  std::optional<InterferenceBvh> sa, sb;
  if (touch_tolerance > 0) {
    sa.emplace(shrunk(a, touch_tolerance / 2), ba.parts(), split);
    sb.emplace(shrunk(b, touch_tolerance / 2), bb.parts(), split);
    InterferenceStats s;
    deep_pairs = intersecting_pairs(*sa, *sb, &s);
    r.stats.node_pairs += s.node_pairs, r.stats.triangle_tests += s.triangle_tests;
    std::size_t k = 0;
    for (auto& p : r.pairs) {  // both lists are ordered by (a, b)
      while (k < deep_pairs.size() && std::pair(deep_pairs[k].a, deep_pairs[k].b) < std::pair(p.a, p.b)) ++k;
      p.penetrating = k < deep_pairs.size() && deep_pairs[k].a == p.a && deep_pairs[k].b == p.b;
    }
    r.penetrating = deep_pairs.size();
  } else {
    r.penetrating = r.pairs.size();
  }
  const InterferenceBvh& ca = sa ? *sa : ba;
  const InterferenceBvh& cb = sb ? *sb : bb;
  const auto& counted = sa ? deep_pairs : r.pairs;
  std::vector<char> a_touched(std::size_t(a.triangles.empty() ? 0 : ca.parts().solids), 0);
  std::vector<char> b_touched(std::size_t(b.triangles.empty() ? 0 : cb.parts().solids), 0);
  for (const auto& p : counted) {
    a_touched[std::size_t(ca.parts().solid_of[std::size_t(p.a)])] = 1;
    b_touched[std::size_t(cb.parts().solid_of[std::size_t(p.b)])] = 1;
  }
  // A solid whose surface crosses nothing of the other is wholly inside or wholly outside it:
  // one corner decides.
  auto nested = [](const InterferenceBvh& self, const std::vector<char>& touched, const InterferenceBvh& other) {
    std::vector<int> inside;
    std::vector<char> seen(touched);
    for (std::size_t pos = 0; pos < self.size(); ++pos) {
      const int solid = self.parts().solid_of[std::size_t(self.triangle_at(int(pos)))];
      if (seen[std::size_t(solid)]) continue;
      seen[std::size_t(solid)] = 1;
      if (other.contains(self.triangle(int(pos))[0])) inside.push_back(solid);
    }
    std::sort(inside.begin(), inside.end());
    return inside;
  };
  r.solids_of_a_inside_b = nested(ca, a_touched, cb);
  r.solids_of_b_inside_a = nested(cb, b_touched, ca);
  r.interferes = r.penetrating > 0 || !r.solids_of_a_inside_b.empty() || !r.solids_of_b_inside_a.empty();
  if (r.pairs.empty() && !r.interferes) {
    InterferenceStats d;
    r.distance = surface_distance(ba, bb, &d);
    r.stats.node_pairs += d.node_pairs, r.stats.triangle_tests += d.triangle_tests;
  }
  return r;
}

}  // namespace mtcs::mesh
