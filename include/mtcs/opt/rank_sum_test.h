#pragma once
// The Wilcoxon rank-sum (Mann–Whitney U) test of two independent samples, e.g. the final
// hypervolumes of two optimiser variants over seeds: do they come from the same distribution?

#include <vector>

namespace mtcs::opt {

struct RankSumTest {
  double u = 0;         // U of the first sample: pairs (a_i, b_j) with a_i > b_j, ties counting 1/2
  double p = 1;         // two-sided p-value
  bool exact = false;   // exact null distribution, or the normal approximation
};

// Exact p (the distribution of U over all equally likely rank assignments) when there are no
// ties and n_a * n_b <= 2500; otherwise the normal approximation with the tie-corrected
// variance and a continuity correction of 1/2. Both samples must be non-empty.
RankSumTest rank_sum_test(const std::vector<double>& a, const std::vector<double>& b);

}  // namespace mtcs::opt
