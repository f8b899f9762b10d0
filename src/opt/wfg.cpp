#include "wfg.h"

#include <algorithm>
#include <iterator>
#include <map>
#include <numeric>

namespace mtcs::opt::detail {
namespace {

template <class Real>
Real area2(const double* rows, std::size_t n, std::size_t stride, const double* ref, std::vector<std::size_t>& order) {
  order.resize(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const double* p = rows + a * stride;
    const double* q = rows + b * stride;
    return p[0] != q[0] ? p[0] < q[0] : p[1] < q[1];
  });
  Real area = 0;
  double best_y = ref[1];
  for (std::size_t k = 0; k < n; ++k) {
    const double* p = rows + order[k] * stride;
    if (p[1] >= best_y) continue;
    std::size_t j = k + 1;
    while (j < n && rows[order[j] * stride + 1] >= p[1]) ++j;
    const double next_x = j < n ? rows[order[j] * stride] : ref[0];
    area += (Real(next_x) - Real(p[0])) * (Real(ref[1]) - Real(p[1]));
    best_y = p[1];
    k = j - 1;
  }
  return area;
}

// The dimension sweep along z over a 2-D staircase.
template <class Real>
Real volume3(const double* rows, std::size_t n, std::size_t stride, const double* ref, std::vector<std::size_t>& order) {
  order.resize(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return rows[a * stride + 2] < rows[b * stride + 2]; });
  std::map<double, double> stair;
  Real area = 0, volume = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double* p = rows + order[k] * stride;
    const double x = p[0], y = p[1];
    auto right = stair.lower_bound(x);
    const double top = right != stair.begin() ? std::prev(right)->second : ref[1];
    const bool covered = top <= y || (right != stair.end() && right->first == x && right->second <= y);
    if (!covered) {
      double at = x, h = top;
      while (right != stair.end() && right->second >= y) {
        area += (Real(right->first) - Real(at)) * (Real(h) - Real(y));
        at = right->first, h = right->second;
        right = stair.erase(right);
      }
      area += (Real(right != stair.end() ? right->first : ref[0]) - Real(at)) * (Real(h) - Real(y));
      stair.emplace_hint(right, x, y);
    }
    const double next_z = k + 1 < n ? rows[order[k + 1] * stride + 2] : ref[2];
    volume += area * (Real(next_z) - Real(p[2]));
  }
  return volume;
}

}  // namespace

template <class Real>
std::vector<double>& Wfg<Real>::level(std::size_t depth) {
  if (rows_.size() <= depth) rows_.resize(depth + 1);
  return rows_[depth];
}

template <class Real>
Real Wfg<Real>::hypervolume(std::vector<double> points) {
  const std::size_t n = points.size() / d_;
  level(0) = std::move(points);
  return hv(0, n, d_);
}

template <class Real>
std::size_t Wfg<Real>::limit_set(const double* p, const double* rows, std::size_t n, std::size_t dims, std::size_t depth,
                                 std::size_t skip, bool by_sum) {
  std::vector<double>& out = level(depth);
  out.resize(n * d_);
  // Branch-free: the outcome is a coin toss per coordinate, which branches mispredict.
  const auto covers = [dims](const double* a, const double* b) {
    bool all = true;
    for (std::size_t k = 0; k < dims; ++k) all &= a[k] <= b[k];
    return all;
  };
  std::size_t m = 0;
  if (!by_sum) {
    // Keep the non-dominated ones as they come: the cheapest for the small sets of the recursion.
    for (std::size_t j = 0; j < n; ++j) {
      if (j == skip) continue;
      double* l = out.data() + m * d_;
      for (std::size_t k = 0; k < dims; ++k) l[k] = std::max(p[k], rows[j * d_ + k]);
      bool dominated = false;
      for (std::size_t i = 0; i < m && !dominated; ++i) dominated = covers(out.data() + i * d_, l);
      if (dominated) continue;
      for (std::size_t i = 0; i < m;) {
        if (covers(l, out.data() + i * d_)) {
          std::copy_n(out.data() + --m * d_, dims, out.data() + i * d_);  // swap-remove
        } else {
          ++i;
        }
      }
      if (l != out.data() + m * d_) std::copy_n(l, dims, out.data() + m * d_);
      ++m;
    }
    return m;
  }
  // By increasing coordinate sum, so that a point is only checked against those kept before it
  // and never evicts one (a dominating point has the smaller sum): pays off on whole fronts.
  std::vector<double>& candidates = scratch_;
  candidates.resize(n * d_);
  order_.clear();
  sums_.resize(n);
  for (std::size_t j = 0; j < n; ++j) {
    if (j == skip) continue;
    double* l = candidates.data() + j * d_;
    double sum = 0;
    for (std::size_t k = 0; k < dims; ++k) sum += l[k] = std::max(p[k], rows[j * d_ + k]);
    sums_[j] = sum;
    order_.push_back(j);
  }
  std::sort(order_.begin(), order_.end(), [&](std::size_t a, std::size_t b) {
    if (sums_[a] != sums_[b]) return sums_[a] < sums_[b];
    // Rounding can tie the sums of a dominating and a dominated point: then the first
    // coordinate where they differ decides.
    return std::lexicographical_compare(candidates.data() + a * d_, candidates.data() + a * d_ + dims,
                                        candidates.data() + b * d_, candidates.data() + b * d_ + dims);
  });
  for (const std::size_t j : order_) {
    const double* l = candidates.data() + j * d_;
    bool dominated = false;
    for (std::size_t i = 0; i < m && !dominated; ++i) dominated = covers(out.data() + i * d_, l);
    if (!dominated) std::copy_n(l, dims, out.data() + m++ * d_);
  }
  return m;
}

template <class Real>
Real Wfg<Real>::hv(std::size_t depth, std::size_t n, std::size_t dims) {
  if (n == 0) return 0;
  const double* ref = ref_.data();
  if (dims == 2) return area2<Real>(level(depth).data(), n, d_, ref, order_);
  if (dims == 3) return volume3<Real>(level(depth).data(), n, d_, ref, order_);
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
  Real volume = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double* p = level(depth).data() + i * d_;
    Real box = 1;
    for (std::size_t k = 0; k + 1 < dims; ++k) box *= Real(ref[k]) - Real(p[k]);
    const std::size_t m = limit_set(p, p + d_, n - i - 1, dims - 1, depth + 1);
    p = level(depth).data() + i * d_;  // level(depth + 1) may have grown rows_
    volume += (Real(ref[dims - 1]) - Real(p[dims - 1])) * (box - hv(depth + 1, m, dims - 1));
  }
  return volume;
}

template <class Real>
Real Wfg<Real>::exclusive(const std::vector<double>& points, std::size_t i, Real& box) {
  const double* p = points.data() + i * d_;
  box = 1;
  for (std::size_t k = 0; k < d_; ++k) box *= Real(ref_[k]) - Real(p[k]);
  last_limit_size_ = limit_set(p, points.data(), points.size() / d_, d_, 0, i, points.size() / d_ >= 128);
  return box - hv(0, last_limit_size_, d_);
}

template <class Real>
std::vector<std::vector<double>> Wfg<Real>::last_limit_set() const {
  // hv() reorders the rows of its level in place but keeps them.
  const std::size_t m = last_limit_size_;
  const std::vector<double>& rows = rows_.front();
  std::vector<std::vector<double>> out;
  for (std::size_t j = 0; j < m; ++j) out.emplace_back(rows.begin() + long(j * d_), rows.begin() + long((j + 1) * d_));
  return out;
}

template class Wfg<double>;
template class Wfg<long double>;

}  // namespace mtcs::opt::detail
