// Accessibility maps of one part, kept per pivot and tool.

#include "mtcs/voxel/access_map_cache.h"

#include <algorithm>
#include <cmath>

namespace mtcs::voxel {

AccessMapCache::AccessMapCache(const mesh::TriangleMesh& part, const GridSpec& grid, SphereGrid sphere, AmMethod method,
                               std::size_t max_maps)
    : octree_(voxelize(part, grid)), sphere_(sphere), method_(method), max_maps_(std::max<std::size_t>(1, max_maps)) {}

std::shared_ptr<const AccessMap> AccessMapCache::at(const Vec3& pivot, const Tool& tool) const {
  Key key{pivot.x(), pivot.y(), pivot.z()};
  for (const ToolCylinder& c : tool) key.insert(key.end(), {c.a, c.b, c.r});
  {
    const std::lock_guard lock(mutex_);
    if (const auto it = maps_.find(key); it != maps_.end()) return it->second;
  }
  // Computed outside the lock: two threads may both compute a missing map, and both get the
  // same cells; the first stored is kept.
  std::shared_ptr<const AccessMap> map;
  if (!octree_.touches_solid(pivot))
    map = std::make_shared<const AccessMap>(compute_access_map(octree_, pivot, tool, sphere_, {.method = method_, .threads = 1}));
  const std::lock_guard lock(mutex_);
  if (maps_.size() >= max_maps_) maps_.clear();
  return maps_.emplace(std::move(key), std::move(map)).first->second;
}

std::size_t AccessMapCache::size() const {
  const std::lock_guard lock(mutex_);
  return maps_.size();
}

namespace {

// Indices whose closed range [k, k + 1] holds x (in cell units), the half-open one first.
std::vector<int> ranges_holding(double x, int n, bool wraps) {
  constexpr double tol = 1e-9;
  const int k = std::clamp(int(std::floor(x)), 0, n - 1);
  std::vector<int> out{k};
  auto add = [&](int m) {
    if (wraps) m = (m + n) % n;
    if (m >= 0 && m < n && std::find(out.begin(), out.end(), m) == out.end()) out.push_back(m);
  };
  if (x - std::floor(x) < tol) add(int(std::floor(x)) - 1);
  if (std::ceil(x) - x < tol) add(int(std::ceil(x)));
  return out;
}

}  // namespace

std::vector<std::array<int, 2>> cells_of(const SphereGrid& sphere, const Vec3& direction) {
  const Vec3 d = direction.normalized();
  const double phi = std::acos(std::clamp(d.z(), -1.0, 1.0));
  double gamma = std::atan2(d.y(), d.x());
  if (gamma < 0) gamma += 2 * M_PI;
  const double x = phi * sphere.rows / M_PI, y = gamma * sphere.cols / (2 * M_PI);
  const std::vector<int> rows = ranges_holding(x, sphere.rows, false);
  std::vector<int> cols = ranges_holding(y, sphere.cols, true);
  if (x < 1e-9 || x > sphere.rows - 1e-9) {  // a pole: in every column of its row
    cols.resize(1);
    for (int j = 0; j < sphere.cols; ++j)
      if (j != cols.front()) cols.push_back(j);
  }
  std::vector<std::array<int, 2>> out;
  for (const int i : rows)
    for (const int j : cols) out.push_back({i, j});
  std::sort(out.begin() + 1, out.end());
  return out;
}

}  // namespace mtcs::voxel
