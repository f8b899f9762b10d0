#include "mtcs/opt/rank_sum_test.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mtcs::opt {
namespace {

// Number of ways n_a of the ranks 1..n_a+n_b give U = k, for every k (k = 0..n_a*n_b): the
// recurrence f(m, n, k) = f(m-1, n, k-n) + f(m, n-1, k) on whether the largest rank is an a.
std::vector<double> u_counts(int na, int nb) {
  // row[n][k] for the current m; m grows from 0.
  std::vector<std::vector<double>> row(std::size_t(nb + 1));
  for (int n = 0; n <= nb; ++n) row[std::size_t(n)] = {1.0};  // m = 0: U = 0, one way
  for (int m = 1; m <= na; ++m) {
    std::vector<std::vector<double>> next(std::size_t(nb + 1));
    for (int n = 0; n <= nb; ++n) {
      std::vector<double>& f = next[std::size_t(n)];
      f.assign(std::size_t(m * n + 1), 0.0);
      const auto& largest_a = row[std::size_t(n)];  // the largest rank is an a: it beats all n b's
      for (std::size_t k = 0; k < largest_a.size(); ++k) f[k + std::size_t(n)] += largest_a[k];
      if (n > 0) {
        const auto& largest_b = next[std::size_t(n - 1)];  // the largest rank is a b: beats no a
        for (std::size_t k = 0; k < largest_b.size(); ++k) f[k] += largest_b[k];
      }
    }
    row = std::move(next);
  }
  return row[std::size_t(nb)];
}

}  // namespace

RankSumTest rank_sum_test(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.empty() || b.empty()) throw std::invalid_argument("rank_sum_test: an empty sample");
  const double na = double(a.size()), nb = double(b.size()), n = na + nb;
  // Midranks of the pooled sample, and the tie term sum(t^3 - t) over groups of equal values.
  std::vector<std::pair<double, int>> pooled;
  for (const double v : a) pooled.push_back({v, 0});
  for (const double v : b) pooled.push_back({v, 1});
  std::sort(pooled.begin(), pooled.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  double rank_sum_a = 0, ties = 0;
  for (std::size_t i = 0; i < pooled.size();) {
    std::size_t j = i;
    while (j < pooled.size() && pooled[j].first == pooled[i].first) ++j;
    const double midrank = 0.5 * double(i + 1 + j);  // ranks i+1 .. j
    const double t = double(j - i);
    ties += t * t * t - t;
    for (std::size_t k = i; k < j; ++k)
      if (pooled[k].second == 0) rank_sum_a += midrank;
    i = j;
  }
  RankSumTest r;
  r.u = rank_sum_a - na * (na + 1) / 2;
  const double mean = na * nb / 2;
  if (ties == 0 && na * nb <= 2500) {
    const std::vector<double> counts = u_counts(int(a.size()), int(b.size()));
    double total = 0, at_most = 0, at_least = 0;
    for (std::size_t k = 0; k < counts.size(); ++k) {
      total += counts[k];
      if (double(k) <= r.u) at_most += counts[k];
      if (double(k) >= r.u) at_least += counts[k];
    }
    r.p = std::min(1.0, 2 * std::min(at_most, at_least) / total);
    r.exact = true;
    return r;
  }
  const double variance = na * nb / 12 * ((n + 1) - ties / (n * (n - 1)));
  if (variance <= 0) return r;  // every value equal: no evidence either way
  const double z = std::max(0.0, std::abs(r.u - mean) - 0.5) / std::sqrt(variance);
  r.p = std::min(1.0, std::erfc(z / std::sqrt(2.0)));
  return r;
}

}  // namespace mtcs::opt
