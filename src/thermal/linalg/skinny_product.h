#pragma once
// Y += B X for a tall B and a few columns X, in single precision: the void's answer to a new
// bore (its layer A^-1 D, the samples' response R D; void_surface.h). Eigen's GEMM packs all of
// B on every call, which for 12 columns costs as much as the product itself; this kernel reads
// B where it lies, stored by rows (B^T column-major: each row of B contiguous, read as one
// stream), in register tiles of 4 rows x 3 columns (AVX2/FMA when the CPU has it, else Eigen's
// product). Private to src/thermal.

#include <Eigen/Dense>

namespace mtcs::thermal {

// y (rows of B x cols of x) += B x, given bt = B^T; bt and x column-major, any sizes.
void add_skinny_product(const Eigen::MatrixXf& bt, const Eigen::MatrixXf& x, Eigen::Ref<Eigen::MatrixXf> y);

// Eigen's product alone, for tests and machines without AVX2.
void add_skinny_product_reference(const Eigen::MatrixXf& bt, const Eigen::MatrixXf& x, Eigen::Ref<Eigen::MatrixXf> y);

}  // namespace mtcs::thermal
