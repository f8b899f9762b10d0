#pragma once
// The line-sink system's dense solve: LU with partial pivoting, picked by size. The result is a
// function of (A, b) alone on a given CPU (no state, no threads), so a warm evaluation equals a
// cold one bit for bit.

#include <Eigen/Dense>

namespace mtcs::thermal {

// Solves A x = b; A is overwritten by its factors. Small systems (a few bores): a plain
// unblocked elimination. Larger ones: a blocked LU whose trailing update is an AVX2/FMA kernel
// when the CPU has it (the plate's 331 unknowns: Eigen's SSE2 LU was ~18 % of a child), else
// Eigen's partialPivLu. Singular A: inf/NaN in x, as Eigen's.
Eigen::VectorXd solve_dense(Eigen::MatrixXd& A, Eigen::VectorXd b);

// The blocked path alone, for tests against the others (falls back as solve_dense does).
Eigen::VectorXd solve_dense_blocked(Eigen::MatrixXd& A, Eigen::VectorXd b);

}  // namespace mtcs::thermal
