#include "wfg.h"

#include <algorithm>
#include <iterator>
#include <map>
#include <numeric>

namespace mtcs::opt::detail {
namespace {

double area2(const double* rows, std::size_t n, std::size_t stride, const double* ref, std::vector<std::size_t>& order) {
  order.resize(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const double* p = rows + a * stride;
    const double* q = rows + b * stride;
    return p[0] != q[0] ? p[0] < q[0] : p[1] < q[1];
  });
  double area = 0, best_y = ref[1];
  for (std::size_t k = 0; k < n; ++k) {
    const double* p = rows + order[k] * stride;
    if (p[1] >= best_y) continue;
    std::size_t j = k + 1;
    while (j < n && rows[order[j] * stride + 1] >= p[1]) ++j;
    const double next_x = j < n ? rows[order[j] * stride] : ref[0];
    area += (next_x - p[0]) * (ref[1] - p[1]);
    best_y = p[1];
    k = j - 1;
  }
  return area;
}

// The dimension sweep along z over a 2-D staircase.
double volume3(const double* rows, std::size_t n, std::size_t stride, const double* ref, std::vector<std::size_t>& order) {
  order.resize(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return rows[a * stride + 2] < rows[b * stride + 2]; });
  std::map<double, double> stair;
  double area = 0, volume = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double* p = rows + order[k] * stride;
    const double x = p[0], y = p[1];
    auto right = stair.lower_bound(x);
    const double top = right != stair.begin() ? std::prev(right)->second : ref[1];
    const bool covered = top <= y || (right != stair.end() && right->first == x && right->second <= y);
    if (!covered) {
      double at = x, h = top;
      while (right != stair.end() && right->second >= y) {
        area += (right->first - at) * (h - y);
        at = right->first, h = right->second;
        right = stair.erase(right);
      }
      area += ((right != stair.end() ? right->first : ref[0]) - at) * (h - y);
      stair.emplace_hint(right, x, y);
    }
    const double next_z = k + 1 < n ? rows[order[k + 1] * stride + 2] : ref[2];
    volume += area * (next_z - p[2]);
  }
  return volume;
}

}  // namespace

std::vector<double>& Wfg::level(std::size_t depth) {
  if (rows_.size() <= depth) rows_.resize(depth + 1);
  return rows_[depth];
}

double Wfg::hypervolume(std::vector<double> points) {
  const std::size_t n = points.size() / d_;
  level(0) = std::move(points);
  return hv(0, n, d_);
}

std::size_t Wfg::limit_set(const double* p, const double* rows, std::size_t n, std::size_t dims, std::size_t depth,
                           std::size_t skip) {
  std::vector<double>& out = level(depth);
  out.resize(n * d_);
  std::size_t m = 0;
  for (std::size_t j = 0; j < n; ++j) {
    if (j == skip) continue;
    double* l = out.data() + m * d_;
    for (std::size_t k = 0; k < dims; ++k) l[k] = std::max(p[k], rows[j * d_ + k]);
    bool dominated = false;
    for (std::size_t i = 0; i < m && !dominated; ++i) {
      const double* o = out.data() + i * d_;
      std::size_t k = 0;
      while (k < dims && o[k] <= l[k]) ++k;
      dominated = k == dims;
    }
    if (dominated) continue;
    // Drop the kept points the new one dominates (swap-remove keeps the array dense).
    for (std::size_t i = 0; i < m;) {
      double* o = out.data() + i * d_;
      std::size_t k = 0;
      while (k < dims && l[k] <= o[k]) ++k;
      if (k == dims) {
        --m;
        std::copy_n(out.data() + m * d_, dims, o);
      } else {
        ++i;
      }
    }
    if (l != out.data() + m * d_) std::copy_n(l, dims, out.data() + m * d_);
    ++m;
  }
  return m;
}

double Wfg::hv(std::size_t depth, std::size_t n, std::size_t dims) {
  if (n == 0) return 0;
  const double* ref = ref_.data();
  if (dims == 2) return area2(level(depth).data(), n, d_, ref, order_);
  if (dims == 3) return volume3(level(depth).data(), n, d_, ref, order_);
  // Worst last coordinate first: each point's limit set among the later ones then lies in its
  // own last coordinate, one dimension fewer.
  {
    std::vector<double>& rows = level(depth);
    order_.resize(n);
    std::iota(order_.begin(), order_.end(), std::size_t{0});
    const std::size_t last = dims - 1;
    std::sort(order_.begin(), order_.end(),
              [&](std::size_t a, std::size_t b) { return rows[a * d_ + last] > rows[b * d_ + last]; });
    std::vector<double> sorted(n * d_);
    for (std::size_t i = 0; i < n; ++i) std::copy_n(rows.data() + order_[i] * d_, d_, sorted.data() + i * d_);
    rows.swap(sorted);
  }
  double volume = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double* p = level(depth).data() + i * d_;
    double box = 1;
    for (std::size_t k = 0; k + 1 < dims; ++k) box *= ref[k] - p[k];
    const std::size_t m = limit_set(p, p + d_, n - i - 1, dims - 1, depth + 1);
    p = level(depth).data() + i * d_;  // level(depth + 1) may have grown rows_
    volume += (ref[dims - 1] - p[dims - 1]) * (box - hv(depth + 1, m, dims - 1));
  }
  return volume;
}

double Wfg::exclusive(const std::vector<double>& points, std::size_t i, double& box) {
  const double* p = points.data() + i * d_;
  box = 1;
  for (std::size_t k = 0; k < d_; ++k) box *= ref_[k] - p[k];
  const std::size_t m = limit_set(p, points.data(), points.size() / d_, d_, 0, i);
  return box - hv(0, m, d_);
}

std::vector<std::vector<double>> Wfg::limit_points(const std::vector<double>& points, std::size_t i) {
  const std::size_t m = limit_set(points.data() + i * d_, points.data(), points.size() / d_, d_, 0, i);
  const std::vector<double>& rows = level(0);
  std::vector<std::vector<double>> out;
  for (std::size_t j = 0; j < m; ++j) out.emplace_back(rows.begin() + long(j * d_), rows.begin() + long((j + 1) * d_));
  return out;
}

}  // namespace mtcs::opt::detail
