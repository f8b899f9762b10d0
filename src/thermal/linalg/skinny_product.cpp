#include "thermal/linalg/skinny_product.h"

#include <immintrin.h>

#include <stdexcept>

#include "thermal/kernels/cpu_features.h"

namespace mtcs::thermal {

namespace {

constexpr int kRows = 4;  // 4 rows x 3 columns: 12 accumulators, 7 loads per 12 FMAs
constexpr int kCols = 3;

// One step of 8 along j: a[r][c] += B(r, j..j+7) * x(j..j+7, c), lane by lane.
template <int R, int C, bool Masked>
__attribute__((target("avx2,fma"), always_inline)) inline void step(__m256 (&a)[R][C], const float* bt, long k,
                                                                    const float* x, long ldx, long j, __m256i mask) {
  __m256 b[R];
  for (int r = 0; r < R; ++r) b[r] = Masked ? _mm256_maskload_ps(bt + r * k + j, mask) : _mm256_loadu_ps(bt + r * k + j);
  for (int c = 0; c < C; ++c) {
    const __m256 xv = Masked ? _mm256_maskload_ps(x + c * ldx + j, mask) : _mm256_loadu_ps(x + c * ldx + j);
    for (int r = 0; r < R; ++r) a[r][c] = _mm256_fmadd_ps(b[r], xv, a[r][c]);
  }
}

// y(r, c) += sum over j of B(r, j) x(j, c) for R rows and C columns; B's rows at bt + r * k.
// Each accumulator sums 8 interleaved partial sums, added at the end: a fixed order, so the
// result is a function of the inputs alone.
template <int R, int C>
__attribute__((target("avx2,fma"))) void tile(const float* bt, long k, const float* x, long ldx, float* y, long ldy,
                                              __m256i tail_mask, long k8) {
  __m256 a[R][C];
  for (int r = 0; r < R; ++r)
    for (int c = 0; c < C; ++c) a[r][c] = _mm256_setzero_ps();
  for (long j = 0; j < k8; j += 8) step<R, C, false>(a, bt, k, x, ldx, j, tail_mask);
  if (k8 < k) step<R, C, true>(a, bt, k, x, ldx, k8, tail_mask);
  for (int r = 0; r < R; ++r)
    for (int c = 0; c < C; ++c) {
      __m128 s = _mm_add_ps(_mm256_castps256_ps128(a[r][c]), _mm256_extractf128_ps(a[r][c], 1));
      s = _mm_add_ps(s, _mm_movehl_ps(s, s));
      s = _mm_add_ss(s, _mm_movehdup_ps(s));
      y[c * ldy + r] += _mm_cvtss_f32(s);
    }
}

template <int R>
__attribute__((target("avx2,fma"))) void row_tile(const float* bt, long k, const float* x, long ldx, long n, float* y,
                                                  long ldy, __m256i tail_mask, long k8) {
  long c = 0;
  for (; c + kCols <= n; c += kCols) tile<R, kCols>(bt, k, x + c * ldx, ldx, y + c * ldy, ldy, tail_mask, k8);
  if (n - c == 2) tile<R, 2>(bt, k, x + c * ldx, ldx, y + c * ldy, ldy, tail_mask, k8);
  if (n - c == 1) tile<R, 1>(bt, k, x + c * ldx, ldx, y + c * ldy, ldy, tail_mask, k8);
}

__attribute__((target("avx2,fma"))) void product_avx2(const float* bt, long k, long m, const float* x, long ldx,
                                                      long n, float* y, long ldy) {
  const long k8 = k - k % 8;
  alignas(32) int lanes[8];
  for (int i = 0; i < 8; ++i) lanes[i] = i < k % 8 ? -1 : 0;
  const __m256i tail_mask = _mm256_load_si256(reinterpret_cast<const __m256i*>(lanes));
  long r = 0;
  for (; r + kRows <= m; r += kRows) row_tile<kRows>(bt + r * k, k, x, ldx, n, y + r, ldy, tail_mask, k8);
  switch (m - r) {
    case 3: row_tile<3>(bt + r * k, k, x, ldx, n, y + r, ldy, tail_mask, k8); break;
    case 2: row_tile<2>(bt + r * k, k, x, ldx, n, y + r, ldy, tail_mask, k8); break;
    case 1: row_tile<1>(bt + r * k, k, x, ldx, n, y + r, ldy, tail_mask, k8); break;
    default: break;
  }
}

}  // namespace

void add_skinny_product_reference(const Eigen::MatrixXf& bt, const Eigen::MatrixXf& x, Eigen::Ref<Eigen::MatrixXf> y) {
  y.noalias() += bt.transpose() * x;
}

void add_skinny_product(const Eigen::MatrixXf& bt, const Eigen::MatrixXf& x, Eigen::Ref<Eigen::MatrixXf> y) {
  if (bt.rows() != x.rows() || y.rows() != bt.cols() || y.cols() != x.cols())
    throw std::invalid_argument("skinny product: the sizes do not match");
  if (!has_avx2_fma()) return add_skinny_product_reference(bt, x, y);
  product_avx2(bt.data(), bt.rows(), bt.cols(), x.data(), x.rows(), x.cols(), y.data(), y.outerStride());
}

}  // namespace mtcs::thermal
