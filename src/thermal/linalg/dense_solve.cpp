// The line-sink system's dense LU. Small systems: unblocked elimination (Eigen's blocked LU costs
// ~3x this at n ~ 40). Large ones (the plate: 331 unknowns, ~24 Mflop per child): a blocked LU
// whose trailing updates A22 -= L21 U12 run in an AVX2/FMA kernel; Eigen is built for SSE2 here
// and its LU ran at ~4 flops per cycle.

#include "thermal/linalg/dense_solve.h"
#include "thermal/kernels/cpu_features.h"

#include <immintrin.h>

#include <algorithm>
#include <cmath>

namespace mtcs::thermal {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

constexpr Index kUnblockedMax = 96;

// Gaussian elimination with partial pivoting (the pivots of Eigen's partialPivLu), in place on
// column-major storage. Compiled twice (below): the rank-1 updates are the whole cost, and this
// build's baseline is SSE2 without FMA.
#define MTCS_UNBLOCKED_BODY                                                           \
  const Index n = A.rows();                                                           \
  double* a = A.data();                                                               \
  for (Index k = 0; k < n; ++k) {                                                     \
    double* ck = a + k * n;                                                           \
    Index p = k;                                                                      \
    double biggest = std::abs(ck[k]);                                                 \
    for (Index i = k + 1; i < n; ++i)                                                 \
      if (std::abs(ck[i]) > biggest) biggest = std::abs(ck[i]), p = i;                \
    if (biggest == 0) continue; /* singular: inf/NaN in x, as Eigen's */              \
    if (p != k) {                                                                     \
      for (Index j = 0; j < n; ++j) std::swap(a[j * n + k], a[j * n + p]);            \
      std::swap(b[k], b[p]);                                                          \
    }                                                                                 \
    const double inv = 1 / ck[k];                                                     \
    for (Index i = k + 1; i < n; ++i) ck[i] *= inv;                                   \
    for (Index j = k + 1; j < n; ++j) {                                               \
      double* __restrict cj = a + j * n;                                              \
      const double akj = cj[k];                                                       \
      if (akj == 0) continue;                                                         \
      for (Index i = k + 1; i < n; ++i) cj[i] -= ck[i] * akj;                         \
    }                                                                                 \
    const double bk = b[k];                                                           \
    for (Index i = k + 1; i < n; ++i) b[i] -= ck[i] * bk;                             \
  }                                                                                   \
  for (Index k = n - 1; k >= 0; --k) {                                                \
    const double* ck = a + k * n;                                                     \
    b[k] /= ck[k];                                                                    \
    const double bk = b[k];                                                           \
    for (Index i = 0; i < k; ++i) b[i] -= ck[i] * bk;                                 \
  }                                                                                   \
  return b;
__attribute__((target("avx2,fma"))) VectorXd solve_unblocked_avx2(MatrixXd& A, VectorXd b) { MTCS_UNBLOCKED_BODY }
VectorXd solve_unblocked_base(MatrixXd& A, VectorXd b) { MTCS_UNBLOCKED_BODY }
#undef MTCS_UNBLOCKED_BODY

VectorXd solve_unblocked(MatrixXd& A, VectorXd b) {
  return has_avx2_fma() ? solve_unblocked_avx2(A, std::move(b)) : solve_unblocked_base(A, std::move(b));
}

// C -= L U (column-major, leading dimension ld): C is m x n, L m x k, U k x n. Blocks of 8 rows
// x 4 columns held in registers over the whole k; the edges in scalar FMA.
__attribute__((target("avx2,fma"))) void subtract_product(double* C, const double* L, const double* U, Index ld,
                                                          Index m, Index n, Index k) {
  const Index m8 = m - m % 8, n4 = n - n % 4;
  for (Index j = 0; j < n4; j += 4) {
    const double* u0 = U + j * ld;
    const double* u1 = u0 + ld;
    const double* u2 = u1 + ld;
    const double* u3 = u2 + ld;
    for (Index i = 0; i < m8; i += 8) {
      __m256d a0 = _mm256_setzero_pd(), b0 = a0, a1 = a0, b1 = a0, a2 = a0, b2 = a0, a3 = a0, b3 = a0;
      const double* l = L + i;
      for (Index p = 0; p < k; ++p, l += ld) {
        const __m256d lo = _mm256_loadu_pd(l), hi = _mm256_loadu_pd(l + 4);
        __m256d u = _mm256_broadcast_sd(u0 + p);
        a0 = _mm256_fmadd_pd(lo, u, a0), b0 = _mm256_fmadd_pd(hi, u, b0);
        u = _mm256_broadcast_sd(u1 + p);
        a1 = _mm256_fmadd_pd(lo, u, a1), b1 = _mm256_fmadd_pd(hi, u, b1);
        u = _mm256_broadcast_sd(u2 + p);
        a2 = _mm256_fmadd_pd(lo, u, a2), b2 = _mm256_fmadd_pd(hi, u, b2);
        u = _mm256_broadcast_sd(u3 + p);
        a3 = _mm256_fmadd_pd(lo, u, a3), b3 = _mm256_fmadd_pd(hi, u, b3);
      }
      double* c = C + j * ld + i;
      const __m256d acc[8] = {a0, b0, a1, b1, a2, b2, a3, b3};
      for (int q = 0; q < 4; ++q, c += ld) {
        _mm256_storeu_pd(c, _mm256_sub_pd(_mm256_loadu_pd(c), acc[2 * q]));
        _mm256_storeu_pd(c + 4, _mm256_sub_pd(_mm256_loadu_pd(c + 4), acc[2 * q + 1]));
      }
    }
  }
  auto edge = [&](Index i, Index j) {
    double s = 0;
    for (Index p = 0; p < k; ++p) s = std::fma(L[p * ld + i], U[j * ld + p], s);
    C[j * ld + i] -= s;
  };
  for (Index j = 0; j < n4; ++j)
    for (Index i = m8; i < m; ++i) edge(i, j);
  for (Index j = n4; j < n; ++j)
    for (Index i = 0; i < m; ++i) edge(i, j);
}

// Right-looking blocked LU with partial pivoting (LAPACK's getrf order): a panel of 32 columns
// unblocked, whole rows swapped, U12 = L11^-1 A12, then A22 -= L21 U12 in the kernel above; then
// the two triangular solves. (A recursive LU with column-wise swaps measured the same out of
// cache and 8 % slower in cache.)
__attribute__((target("avx2,fma"))) VectorXd solve_blocked_avx2(MatrixXd& A, VectorXd b) {
  constexpr Index kPanel = 32;
  const Index n = A.rows(), ld = n;
  double* a = A.data();
  for (Index k0 = 0; k0 < n; k0 += kPanel) {
    const Index k1 = std::min(n, k0 + kPanel);
    for (Index k = k0; k < k1; ++k) {
      double* ck = a + k * ld;
      Index p = k;
      double biggest = std::abs(ck[k]);
      for (Index i = k + 1; i < n; ++i)
        if (std::abs(ck[i]) > biggest) biggest = std::abs(ck[i]), p = i;
      if (biggest == 0) continue;  // singular: inf/NaN in the back substitution
      if (p != k) {
        for (Index j = 0; j < n; ++j) std::swap(a[j * ld + k], a[j * ld + p]);
        std::swap(b[k], b[p]);
      }
      const double inv = 1 / ck[k];
      for (Index i = k + 1; i < n; ++i) ck[i] *= inv;
      for (Index j = k + 1; j < k1; ++j) {
        double* cj = a + j * ld;
        const double akj = cj[k];
        if (akj == 0) continue;
        for (Index i = k + 1; i < n; ++i) cj[i] -= ck[i] * akj;
      }
    }
    if (k1 == n) break;
    for (Index j = k1; j < n; ++j) {  // U12 = L11^-1 A12 (unit lower triangle)
      double* cj = a + j * ld;
      for (Index k = k0; k < k1; ++k) {
        const double akj = cj[k];
        if (akj == 0) continue;
        const double* ck = a + k * ld;
        for (Index i = k + 1; i < k1; ++i) cj[i] -= ck[i] * akj;
      }
    }
    subtract_product(a + k1 * ld + k1, a + k0 * ld + k1, a + k1 * ld + k0, ld, n - k1, n - k1, k1 - k0);
  }
  for (Index k = 0; k < n; ++k) {  // L y = P b
    const double* ck = a + k * ld;
    const double bk = b[k];
    for (Index i = k + 1; i < n; ++i) b[i] -= ck[i] * bk;
  }
  for (Index k = n - 1; k >= 0; --k) {  // U x = y
    const double* ck = a + k * ld;
    b[k] /= ck[k];
    const double bk = b[k];
    for (Index i = 0; i < k; ++i) b[i] -= ck[i] * bk;
  }
  return b;
}

}  // namespace

VectorXd solve_dense_blocked(MatrixXd& A, VectorXd b) {
  if (!has_avx2_fma()) return A.partialPivLu().solve(b);
  return solve_blocked_avx2(A, std::move(b));
}

VectorXd solve_dense(MatrixXd& A, VectorXd b) {
  if (A.rows() <= kUnblockedMax) return solve_unblocked(A, std::move(b));
  return solve_dense_blocked(A, std::move(b));
}

}  // namespace mtcs::thermal
