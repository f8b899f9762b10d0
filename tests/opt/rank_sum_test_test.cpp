// The rank-sum test against hand-computed textbook cases and a brute-force null distribution.

#include <catch2/catch.hpp>
#include <cmath>
#include <numeric>
#include <random>

#include "mtcs/opt/rank_sum_test.h"

using mtcs::opt::rank_sum_test;

TEST_CASE("rank-sum test: exact p of a small untied example, by hand", "[opt][statistics]") {
  // Ages at diagnosis, men {19, 22, 16, 29, 24} and women {20, 11, 17, 12} (the example of
  // scipy.stats.mannwhitneyu's documentation). Pooled ranks of the men: 3, 5, 7, 8, 9, sum 32,
  // so U = 32 - 5*6/2 = 17 of 20 pairs. Under the null every one of C(9,4) = 126 rank sets is
  // equally likely; U >= 17 mirrors U <= 3, which 1 + 1 + 2 + 3 = 7 sets give (U = 0, 1, 2, 3).
  // Two-sided p = 2 * 7 / 126.
  const auto t = rank_sum_test({19, 22, 16, 29, 24}, {20, 11, 17, 12});
  CHECK(t.exact);
  CHECK(t.u == 17);
  CHECK(t.p == Approx(14.0 / 126).epsilon(1e-12));
  const auto mirrored = rank_sum_test({20, 11, 17, 12}, {19, 22, 16, 29, 24});
  CHECK(mirrored.u == 3);
  CHECK(mirrored.p == Approx(t.p).epsilon(1e-12));
  // Completely separated samples of 3 and 3: U = 0 and p = 2 / C(6,3) = 0.1.
  CHECK(rank_sum_test({1, 2, 3}, {4, 5, 6}).p == Approx(0.1).epsilon(1e-12));
}

TEST_CASE("rank-sum test: ties use midranks and the tie-corrected normal approximation, by hand", "[opt][statistics]") {
  // A = {1, 2, 2, 3}, B = {2, 3, 4, 5}. Midranks: 1 -> 1; the three 2s -> 3; the two 3s -> 5.5;
  // 4 -> 7; 5 -> 8. R_A = 1 + 3 + 3 + 5.5 = 12.5, U = 12.5 - 10 = 2.5 (pairs: 0 + 0.5 + 0.5 + 1.5).
  // Mean 8; variance 4*4/12 * (9 - (3^3-3 + 2^3-2) / (8*7)) = 4/3 * (9 - 30/56) = 11.2857142857;
  // z = (|2.5 - 8| - 0.5) / sqrt(11.2857142857) = 1.48835; p = erfc(z / sqrt 2) = 0.136658247738.
  const auto t = rank_sum_test({1, 2, 2, 3}, {2, 3, 4, 5});
  CHECK_FALSE(t.exact);
  CHECK(t.u == 2.5);
  CHECK(t.p == Approx(0.13665824773814753).epsilon(1e-12));
  // Every value equal: nothing to tell the samples apart.
  CHECK(rank_sum_test({0, 0, 0}, {0, 0}).p == 1);
}

TEST_CASE("rank-sum test: the exact p equals a count over every rank assignment", "[opt][statistics]") {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> normal;
  for (int trial = 0; trial < 20; ++trial) {
    const int na = 2 + trial % 5, nb = 3 + trial % 4;
    std::vector<double> a(static_cast<std::size_t>(na)), b(static_cast<std::size_t>(nb));
    for (auto& v : a) v = normal(rng) + 0.8;
    for (auto& v : b) v = normal(rng);
    const auto t = rank_sum_test(a, b);
    REQUIRE(t.exact);
    // Brute force: every subset of na of the n ranks as the a's, its U, and how extreme it is.
    const int n = na + nb;
    long total = 0, at_most = 0, at_least = 0;
    for (unsigned mask = 0; mask < (1u << n); ++mask) {
      if (__builtin_popcount(mask) != na) continue;
      double rank_sum = 0;
      for (int k = 0; k < n; ++k)
        if (mask >> k & 1u) rank_sum += k + 1;
      const double u = rank_sum - na * (na + 1) / 2.0;
      ++total;
      at_most += u <= t.u;
      at_least += u >= t.u;
    }
    CHECK(t.p == Approx(std::min(1.0, 2.0 * double(std::min(at_most, at_least)) / double(total))).epsilon(1e-12));
  }
}
