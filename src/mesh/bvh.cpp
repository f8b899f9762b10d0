#include "mtcs/mesh/bvh.h"

#include "ray_parity.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>


namespace mtcs::mesh {
namespace {

double box_box_distance(const Box& a, const Box& b) { return std::sqrt(geometry::box_distance_sq(a, b)); }

// Ray-triangle crossing (Moeller-Trumbore): the ray parameter, or a negative value for none.
double ray_hit(const Vec3& o, const Vec3& d, const std::array<Vec3, 3>& t) {
  const Vec3 e1 = t[1] - t[0], e2 = t[2] - t[0];
  const Vec3 p = d.cross(e2);
  const double det = e1.dot(p);
  if (det == 0) return -1;
  const double inv = 1 / det;
  const Vec3 s = o - t[0];
  const double u = s.dot(p) * inv;
  if (u < 0 || u > 1) return -1;
  const Vec3 q = s.cross(e1);
  const double v = d.dot(q) * inv;
  if (v < 0 || u + v > 1) return -1;
  return e2.dot(q) * inv;
}


// The edges one query has examined, keyed by their vertex indices: open addressing in a fixed
// table, cleared by bumping a stamp. When it fills up, edges are simply examined again.
class EdgeSet {
 public:
  void clear() {
    if (++stamp_ == 0) std::fill(stamps_.begin(), stamps_.end(), 0u), stamp_ = 1;
    size_ = 0;
  }
  bool contains(std::uint64_t key) const {
    for (std::size_t i = hash(key);; i = (i + 1) & kMask) {
      if (stamps_[i] != stamp_) return false;
      if (keys_[i] == key) return true;
    }
  }
  void insert(std::uint64_t key) {
    if (size_ >= kSize / 2) return;
    std::size_t i = hash(key);
    while (stamps_[i] == stamp_) {
      if (keys_[i] == key) return;
      i = (i + 1) & kMask;
    }
    stamps_[i] = stamp_, keys_[i] = key, ++size_;
  }

 private:
  static constexpr std::size_t kSize = 4096, kMask = kSize - 1;
  static std::size_t hash(std::uint64_t key) { return std::size_t((key * 0x9E3779B97F4A7C15ull) >> 52); }
  std::array<std::uint64_t, kSize> keys_{};
  std::array<std::uint32_t, kSize> stamps_{};
  std::uint32_t stamp_ = 0;
  std::size_t size_ = 0;
};

std::uint64_t edge_key(int a, int b) {
  return a < b ? (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b)
               : (std::uint64_t(std::uint32_t(b)) << 32) | std::uint32_t(a);
}

}  // namespace

TriangleBvh::TriangleBvh(const TriangleMesh& mesh, SplitRule split_rule) : split_rule_(split_rule) {
  tris_.reserve(mesh.triangles.size());
  corners_ = mesh.triangles;
  std::vector<Vec3> centroids;
  centroids.reserve(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    tris_.push_back({mesh.corner(t, 0), mesh.corner(t, 1), mesh.corner(t, 2)});
    centroids.push_back((tris_.back()[0] + tris_.back()[1] + tris_.back()[2]) / 3);
  }
  nodes_.reserve(tris_.size() / 2 + 2);
  nodes_.resize(1);
  build(0, 0, int(tris_.size()), 0, centroids);
  spheres_.reserve(tris_.size());
  for (std::size_t i = 0; i < tris_.size(); ++i) {
    const Vec3 c = centroids[i];
    spheres_.push_back({c, std::max({(tris_[i][0] - c).norm(), (tris_[i][1] - c).norm(), (tris_[i][2] - c).norm()})});
  }
}

// Binned surface-area heuristic along `axis`: how many triangles (in centroid order) go left so
// that (left count x left box area + right count x right box area) is least.
int TriangleBvh::sah_split(int first, int count, int axis, const Box& cbox, const std::vector<Vec3>& centroids) const {
  constexpr int kBins = 16;
  const double lo = cbox.min[axis], width = cbox.max[axis] - lo;
  if (!(width > 0)) return count / 2;
  std::array<Box, kBins> boxes;
  std::array<int, kBins> counts{};
  boxes.fill(Box::empty());
  for (int i = first; i < first + count; ++i) {
    const int b = std::min(kBins - 1, int(kBins * (centroids[i][axis] - lo) / width));
    ++counts[b];
    for (const Vec3& v : tris_[i]) boxes[b].min = boxes[b].min.cwiseMin(v), boxes[b].max = boxes[b].max.cwiseMax(v);
  }
  auto area = [](const Box& b) {
    const Vec3 e = (b.max - b.min).cwiseMax(0.0);
    return e.x() * e.y() + e.y() * e.z() + e.z() * e.x();
  };
  std::array<double, kBins> right_cost{};  // right_cost[b]: bins b.. on the right
  Box acc = Box::empty();
  int n = 0;
  for (int b = kBins - 1; b > 0; --b) {
    acc.min = acc.min.cwiseMin(boxes[b].min), acc.max = acc.max.cwiseMax(boxes[b].max), n += counts[b];
    right_cost[b] = n > 0 ? n * area(acc) : 0;
  }
  acc = Box::empty();
  n = 0;
  int best_left = count / 2;
  double best = std::numeric_limits<double>::infinity();
  for (int b = 1; b < kBins; ++b) {
    acc.min = acc.min.cwiseMin(boxes[b - 1].min), acc.max = acc.max.cwiseMax(boxes[b - 1].max), n += counts[b - 1];
    if (n == 0 || n == count) continue;
    const double cost = n * area(acc) + right_cost[b];
    if (cost < best) best = cost, best_left = n;
  }
  return best_left;
}

void TriangleBvh::build(int node, int first, int count, int depth, std::vector<Vec3>& centroids) {
  Box box = Box::empty(), cbox = Box::empty();
  for (int i = first; i < first + count; ++i) {
    for (const Vec3& v : tris_[i]) box.min = box.min.cwiseMin(v), box.max = box.max.cwiseMax(v);
    cbox.min = cbox.min.cwiseMin(centroids[i]), cbox.max = cbox.max.cwiseMax(centroids[i]);
  }
  if (count <= 4) {
    nodes_[node] = {box, first, count};
    return;
  }
  int axis = 0;
  (cbox.max - cbox.min).maxCoeff(&axis);
  // Below depth 48 the median: bounds the depth (the stack traversals hold 128 entries) whatever
  // the heuristic makes of a mesh.
  const bool sah = split_rule_ == SplitRule::SurfaceArea && depth < 48;
  const int half = sah ? sah_split(first, count, axis, cbox, centroids) : count / 2;
  // Reorder triangles, centroids and corners together: the `half` lowest centroids go left.
  std::vector<int> order(count);
  std::iota(order.begin(), order.end(), first);
  std::nth_element(order.begin(), order.begin() + half, order.end(),
                   [&](int a, int b) { return centroids[a][axis] < centroids[b][axis]; });
  std::vector<std::array<Vec3, 3>> tris(count);
  std::vector<Vec3> cents(count);
  std::vector<std::array<int, 3>> corners(count);
  for (int i = 0; i < count; ++i) tris[i] = tris_[order[i]], cents[i] = centroids[order[i]], corners[i] = corners_[order[i]];
  std::copy(tris.begin(), tris.end(), tris_.begin() + first);
  std::copy(cents.begin(), cents.end(), centroids.begin() + first);
  std::copy(corners.begin(), corners.end(), corners_.begin() + first);

  const int left = int(nodes_.size());
  nodes_.resize(nodes_.size() + 2);
  nodes_[node] = {box, left, 0};
  build(left, first, half, depth + 1, centroids);
  build(left + 1, first + half, count - half, depth + 1, centroids);
}

double TriangleBvh::segment_distance(const Vec3& p0, const Vec3& p1, double cap) const {
  if (tris_.empty()) return cap;
  const Box seg{p0.cwiseMin(p1), p0.cwiseMax(p1)};
  double best = cap;
  int stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (box_box_distance(seg, node.box) >= best) continue;
    if (node.count > 0) {
      for (int i = node.first; i < node.first + node.count; ++i)
        best = std::min(best, geometry::segment_triangle_distance(p0, p1, tris_[i][0], tris_[i][1], tris_[i][2]));
      continue;
    }
    // Nearer child last, so that it is visited first.
    const double dl = box_box_distance(seg, nodes_[node.first].box);
    const double dr = box_box_distance(seg, nodes_[node.first + 1].box);
    if (dl < dr) stack[top++] = node.first + 1, stack[top++] = node.first;
    else stack[top++] = node.first, stack[top++] = node.first + 1;
  }
  return best;
}

template <class Leaf>
void TriangleBvh::visit_ray(const Vec3& p, const Vec3& d, Leaf&& leaf) const {
  const Vec3 inv = d.cwiseInverse();
  int stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (!detail::ray_meets_box(p, inv, node.box)) continue;
    if (node.count > 0) {
      for (int i = node.first; i < node.first + node.count; ++i) leaf(tris_[i]);
      continue;
    }
    stack[top++] = node.first;
    stack[top++] = node.first + 1;
  }
}

bool TriangleBvh::contains(const Vec3& p) const {
  if (tris_.empty() || !bounds().contains(p)) return false;
  return detail::inside_by_parity(p, [this](const Vec3& o, const Vec3& d, auto&& on_triangle) { visit_ray(o, d, on_triangle); });
}

std::optional<TriangleBvh::Hit> TriangleBvh::first_hit(const Vec3& p, const Vec3& d) const {
  if (tris_.empty()) return std::nullopt;
  std::optional<Hit> best;
  visit_ray(p, d, [&](const std::array<Vec3, 3>& tri) {
    const double t = ray_hit(p, d, tri);
    if (t > 0 && (!best || t < best->t)) best = Hit{t, (tri[1] - tri[0]).cross(tri[2] - tri[0]).normalized()};
  });
  return best;
}

geometry::TriangleDistanceResult TriangleBvh::cylinder_distance(const geometry::Cylinder& cyl, double cap) const {
  geometry::TriangleDistanceResult best{cap, Vec3::Zero(), Vec3::Zero(), true};
  if (tris_.empty()) return best;
  // Node tests, all cheap (an exact segment-box distance costs more than it saves):
  //  * lower bound, for ordering and pruning: the larger of the cylinder's box (half-extent
  //    r sqrt(1 - w_k^2) along axis k) to the node's box, the capsule to the node's bounding
  //    sphere, and how far the node lies beyond an end plane;
  //  * a node the axis misses even when its box is grown by best + r along every axis (a cube
  //    around each point contains the ball) holds nothing closer than best.
  const Vec3 axis = cyl.p1 - cyl.p0;
  const double len2 = axis.squaredNorm();
  const Vec3 half = len2 > 0 ? Vec3(cyl.radius * (Vec3::Ones() - axis.cwiseAbs2() / len2).cwiseMax(0.0).cwiseSqrt())
                             : Vec3(cyl.radius, cyl.radius, 0);
  const Box cyl_box{cyl.p0.cwiseMin(cyl.p1) - half, cyl.p0.cwiseMax(cyl.p1) + half};
  const double len = std::sqrt(len2);
  const Vec3 w = len > 0 ? Vec3(axis / len) : Vec3::UnitZ();
  const double inv_len2 = len2 > 0 ? 1 / len2 : 0;
  auto axis_dist2 = [&](const Vec3& p) {  // squared distance from p to the axis segment
    const Vec3 q = p - cyl.p0;
    const double t = std::clamp(q.dot(axis) * inv_len2, 0.0, 1.0);
    return (q - t * axis).squaredNorm();
  };
  auto lower_bound = [&](const Box& box) {
    const Vec3 center = (box.min + box.max) / 2, extent = box.max - center;
    const double sphere = std::sqrt(axis_dist2(center)) - extent.norm() - cyl.radius;
    // The box beyond an end plane: the capsule bound is weakest there.
    const double t = w.dot(center - cyl.p0), spread = w.cwiseAbs().dot(extent);
    const double slab = std::max(-(t + spread), t - spread - len);
    return std::max({box_box_distance(cyl_box, box), sphere, slab});
  };
  const Vec3 inv_axis = axis.cwiseInverse();
  auto axis_reaches = [&](const Box& box, double grow) {
    double t0 = 0, t1 = 1;
    for (int k = 0; k < 3; ++k) {
      const double lo = box.min[k] - grow, hi = box.max[k] + grow;
      if (axis[k] == 0) {
        if (cyl.p0[k] < lo || cyl.p0[k] > hi) return false;
        continue;
      }
      double a = (lo - cyl.p0[k]) * inv_axis[k], b = (hi - cyl.p0[k]) * inv_axis[k];
      if (a > b) std::swap(a, b);
      t0 = std::max(t0, a), t1 = std::min(t1, b);
      if (t0 > t1) return false;
    }
    return true;
  };
  // Best-first: the node with the smallest bound next, so that the nearest triangles are met
  // early and the cap tightens before the far ones are reached.
  struct Entry {
    double bound;
    int node;
    bool operator<(const Entry& o) const { return bound > o.bound; }  // min-heap
  };
  thread_local std::vector<Entry> heap;
  heap.clear();
  // An edge's distance, once folded into `best`, cannot lower it again: each is examined once.
  thread_local EdgeSet seen;
  seen.clear();
  heap.push_back({lower_bound(nodes_[0].box), 0});
  while (!heap.empty()) {
    std::pop_heap(heap.begin(), heap.end());
    const Entry e = heap.back();
    heap.pop_back();
    if (e.bound >= best.distance) break;  // every other entry is farther
    const Node& node = nodes_[e.node];
    if (!axis_reaches(node.box, best.distance + cyl.radius)) continue;
    if (node.count > 0) {
      for (int i = node.first; i < node.first + node.count; ++i) {
        const double reach = best.distance + spheres_[i].radius + cyl.radius;
        if (axis_dist2(spheres_[i].center) >= reach * reach) continue;
        const auto& v = corners_[i];
        const std::uint64_t keys[3] = {edge_key(v[0], v[1]), edge_key(v[1], v[2]), edge_key(v[2], v[0])};
        unsigned skip = 0;
        for (unsigned k = 0; k < 3; ++k) skip |= unsigned(seen.contains(keys[k])) << k;
        const auto d = geometry::distance(cyl, {tris_[i][0], tris_[i][1], tris_[i][2]}, {.upper_bound = best.distance}, skip);
        for (unsigned k = 0; k < 3; ++k)
          if (d.edges_examined >> k & 1u) seen.insert(keys[k]);
        if (d.bounded) continue;
        best = d;
        if (d.intersecting()) return best;
      }
      continue;
    }
    for (const int child : {node.first, node.first + 1}) {
      const double bound = lower_bound(nodes_[child].box);
      if (bound >= best.distance) continue;
      heap.push_back({bound, child});
      std::push_heap(heap.begin(), heap.end());
    }
  }
  return best;
}

Clearance cylinder_clearance(const TriangleBvh& bvh, const geometry::Cylinder& cylinder, double upper_bound) {
  // A cylinder whose axis midpoint is inside the solid meets it: buried or crossing the
  // surface, the distance is 0 either way. One ray cast settles that before the search, which
  // would otherwise look for the nearest triangle of a buried cylinder in vain.
  // An axis end outside the mesh's box puts part of the cylinder outside the solid: it cannot
  // be buried, and crossing is the search's to find. Bores drilled from a block face mostly
  // start there, and skip the ray.
  const Vec3 mid = (cylinder.p0 + cylinder.p1) / 2;
  const bool may_be_inside = bvh.bounds().contains(cylinder.p0) && bvh.bounds().contains(cylinder.p1);
  if (may_be_inside && bvh.contains(mid)) {
    // The smallest cap: the search visits only what may touch, to tell buried from crossing.
    const auto touch = bvh.cylinder_distance(cylinder, std::numeric_limits<double>::denorm_min());
    if (touch.bounded) return {0, false, true, mid, mid};
    return {0, false, false, touch.on_cylinder, touch.on_triangle};
  }
  // Not inside: no contact with the surface means wholly outside.
  const auto d = bvh.cylinder_distance(cylinder, upper_bound);
  return {d.distance, d.bounded, false, d.on_cylinder, d.on_triangle};
}

}  // namespace mtcs::mesh
