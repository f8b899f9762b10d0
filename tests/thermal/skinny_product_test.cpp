// The void's tall-times-few-columns product (src/thermal/linalg/skinny_product.cpp) against the same
// product in double precision (Eigen), over shapes with every row and column remainder.

#include <catch2/catch.hpp>

#include <Eigen/Dense>

#include "thermal/linalg/skinny_product.h"

using Eigen::MatrixXd;
using Eigen::MatrixXf;

TEST_CASE("skinny product: y += b x as in double precision, any remainder of rows and columns", "[thermal][skinny]") {
  std::srand(7);
  for (const int m : {1, 2, 3, 4, 5, 7, 33, 442, 2061})
    for (const int k : {1, 3, 8, 9, 442})
      for (const int n : {1, 2, 3, 4, 5, 12, 13}) {
        const MatrixXf b = MatrixXf::Random(m, k), x = MatrixXf::Random(k, n), y0 = MatrixXf::Random(m, n);
        MatrixXf y = y0;
        mtcs::thermal::add_skinny_product(b.transpose(), x, y);
        const MatrixXd exact = y0.cast<double>() + b.cast<double>() * x.cast<double>();
        // Float sums of k terms of size <= 1: within k ulps of the largest term.
        const double bound = 4 * k * double(std::numeric_limits<float>::epsilon());
        INFO("m " << m << " k " << k << " n " << n);
        REQUIRE((y.cast<double>() - exact).cwiseAbs().maxCoeff() <= bound);
        MatrixXf z = y0;
        mtcs::thermal::add_skinny_product_reference(b.transpose(), x, z);
        REQUIRE((z.cast<double>() - exact).cwiseAbs().maxCoeff() <= bound);
      }
}

TEST_CASE("skinny product: into a block of a larger matrix, the rest untouched", "[thermal][skinny]") {
  const MatrixXf b = MatrixXf::Random(37, 20), x = MatrixXf::Random(20, 4);
  MatrixXf big = MatrixXf::Constant(50, 9, 3.0f);
  mtcs::thermal::add_skinny_product(b.transpose(), x, big.block(5, 2, 37, 4));
  const MatrixXf expected = MatrixXf::Constant(37, 4, 3.0f) + b * x;
  CHECK((big.block(5, 2, 37, 4) - expected).cwiseAbs().maxCoeff() <= 1e-4f);
  MatrixXf outside = big;
  outside.block(5, 2, 37, 4).setConstant(3.0f);
  CHECK((outside.array() == 3.0f).all());
}

TEST_CASE("skinny product: sizes that do not match are refused", "[thermal][skinny]") {
  MatrixXf y = MatrixXf::Zero(4, 2);
  CHECK_THROWS_AS(mtcs::thermal::add_skinny_product(MatrixXf::Ones(3, 4), MatrixXf::Ones(2, 2), y), std::invalid_argument);
}
