// The line-sink system's dense solve (src/thermal/dense_solve.cpp) against a second method,
// Eigen's full-pivoting LU, on random systems of the sizes the models produce (a few bores: n ~
// 40; the plate: n = 331), and its determinism: the same system solved twice gives the same bits.
#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <vector>

#include "thermal/dense_solve.h"

using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

// Dense, unsymmetric, rows of very different scales, and a weak diagonal in some rows (partial
// pivoting has to swap): like the collocation system's film rows next to its balance row.
MatrixXd random_system(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  MatrixXd A(n, n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) A(i, j) = u(rng);
  for (int i = 0; i < n; ++i) {
    A(i, i) += (i % 7 == 3) ? 0.0 : 4.0;
    A.row(i) *= std::pow(10.0, (i % 5) - 2);
  }
  return A;
}

// The best of `runs` solves of a copy of A, in microseconds (the bench cases below).
template <class Solve>
double best_us(const MatrixXd& A, int runs, Solve&& solve) {
  double best = 1e300;
  for (int r = 0; r < runs; ++r) {
    MatrixXd w = A;
    const auto t0 = std::chrono::steady_clock::now();
    const VectorXd x = solve(w);
    best = std::min(best, std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count());
    REQUIRE(x.allFinite());
  }
  return best;
}

}  // namespace

TEST_CASE("dense solve: blocked and unblocked LU agree with a full-pivoting LU", "[thermal][dense_solve]") {
  for (int n : {7, 40, 96, 97, 130, 331}) {
    const MatrixXd A = random_system(n, 11u + unsigned(n));
    VectorXd b(n);
    for (int i = 0; i < n; ++i) b[i] = std::sin(0.3 * i) * std::pow(10.0, (i % 5) - 2);
    const VectorXd reference = A.fullPivLu().solve(b);
    MatrixXd work = A;
    const VectorXd x = mtcs::thermal::solve_dense(work, b);
    INFO("n = " << n);
    CHECK((x - reference).norm() <= 1e-11 * reference.norm());
    CHECK((A * x - b).norm() <= 1e-12 * (A.norm() * x.norm()));
    if (n > 40) {
      work = A;
      const VectorXd y = mtcs::thermal::solve_dense_blocked(work, b);
      CHECK((y - reference).norm() <= 1e-11 * reference.norm());
    }
  }
}

TEST_CASE("dense solve: the same system gives the same bits", "[thermal][dense_solve]") {
  const MatrixXd A = random_system(331, 5);
  const VectorXd b = VectorXd::LinSpaced(331, -1, 2);
  MatrixXd w1 = A, w2 = A;
  const VectorXd x1 = mtcs::thermal::solve_dense(w1, b);
  const VectorXd x2 = mtcs::thermal::solve_dense(w2, b);
  for (int i = 0; i < 331; ++i) REQUIRE(std::memcmp(&x1[i], &x2[i], sizeof(double)) == 0);
}

TEST_CASE("dense solve: a singular system gives non-finite values, not a wrong answer", "[thermal][dense_solve]") {
  MatrixXd A = random_system(150, 3);
  A.col(70).setZero();  // no pivot in column 70
  MatrixXd work = A;
  const VectorXd x = mtcs::thermal::solve_dense(work, VectorXd::Ones(150));
  CHECK_FALSE(x.allFinite());
}

// Hidden: the plate's system size, best of 200 solves, this LU against Eigen's partialPivLu.
TEST_CASE("dense solve: best time at n = 331", "[.bench][dense_solve]") {
  const MatrixXd A = random_system(331, 9);
  const VectorXd b = VectorXd::LinSpaced(331, -1, 2);
  const double ours = 1e-3 * best_us(A, 200, [&](MatrixXd& w) { return mtcs::thermal::solve_dense(w, b); });
  const double eigen = 1e-3 * best_us(A, 200, [&](MatrixXd& w) { return VectorXd(w.partialPivLu().solve(b)); });
  std::printf("dense solve n=331, best of 200: solve_dense %.3f ms, Eigen partialPivLu %.3f ms\n", ours, eigen);
  // Out of cache, as in a child's evaluation: 40 different systems (35 MB) in turn, mean.
  std::vector<MatrixXd> many;
  for (int i = 0; i < 40; ++i) many.push_back(random_system(331, 100u + unsigned(i)));
  auto cold_ms = [&](auto&& solve) {
    const auto t0 = std::chrono::steady_clock::now();
    for (int r = 0; r < 5; ++r)
      for (MatrixXd w : many) REQUIRE(solve(w).allFinite());
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count() / 200;
  };
  for (int r = 0; r < 2; ++r)
    std::printf("out of cache, mean of 200 (copy included): solve_dense %.3f ms, Eigen %.3f ms\n",
                cold_ms([&](MatrixXd& w) { return mtcs::thermal::solve_dense(w, b); }),
                cold_ms([&](MatrixXd& w) { return VectorXd(w.partialPivLu().solve(b)); }));
}

// Hidden: the sizes of a few bores' systems (T2d, 12 unknowns per bore), best of 2 000.
TEST_CASE("dense solve: best time at n = 40 and 80", "[.bench][dense_solve]") {
  for (int n : {40, 80}) {
    const MatrixXd A = random_system(n, 9);
    const VectorXd b = VectorXd::LinSpaced(n, -1, 2);
    std::printf("dense solve n=%d, best of 2000: solve_dense %.2f us, blocked %.2f us\n", n,
                best_us(A, 2000, [&](MatrixXd& w) { return mtcs::thermal::solve_dense(w, b); }),
                best_us(A, 2000, [&](MatrixXd& w) { return mtcs::thermal::solve_dense_blocked(w, b); }));
  }
}
