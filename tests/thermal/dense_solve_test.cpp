// The line-sink system's dense solve (src/thermal/linalg/dense_solve.cpp) against a second method,
// Eigen's full-pivoting LU, on random systems of the sizes the models produce (a few bores: n ~
// 40; the plate: n = 331), and its determinism: the same system solved twice gives the same bits.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <vector>

#include "thermal/linalg/dense_solve.h"

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

