#pragma once
// WFG (While, Bradstreet & Barone 2012) on flat arrays: the hypervolume of d >= 2 objectives,
// and one point's exclusive volume as its box minus the hypervolume of its limit set. `Real`
// carries the sums and products (coordinates stay double: the limit set's maxima are exact);
// long double makes box-minus-the-rest 2 000 times less prone to cancel.

#include <cstddef>
#include <vector>

namespace mtcs::opt::detail {

template <class Real>
class Wfg {
 public:
  explicit Wfg(std::vector<double> ref) : ref_(std::move(ref)), d_(ref_.size()) {}

  // points: n rows of d coordinates, each strictly inside the reference box.
  Real hypervolume(std::vector<double> points);

  // Row i's box minus the hypervolume of its limit set {max(p_i, q)} over the other rows (all
  // strictly inside the reference box). Cancels when the result is tiny next to the box: `box`
  // receives the box's volume so the caller can judge.
  Real exclusive(const std::vector<double>& points, std::size_t i, Real& box);
  // The non-dominated limit set of the last `exclusive` call, as points.
  std::vector<std::vector<double>> last_limit_set() const;

 private:
  // Hypervolume of the n rows in rows_[depth] in the first `dims` coordinates (stride d_).
  Real hv(std::size_t depth, std::size_t n, std::size_t dims);
  // Writes the non-dominated set of {max(p, q)} (first `dims` coordinates) into rows_[depth]
  // and returns its size.
  std::size_t limit_set(const double* p, const double* rows, std::size_t n, std::size_t dims, std::size_t depth,
                        std::size_t skip = std::size_t(-1), bool by_sum = false);
  std::vector<double>& level(std::size_t depth);

  std::vector<double> ref_;
  std::size_t d_;
  std::vector<std::vector<double>> rows_;  // per recursion depth
  std::vector<std::size_t> order_;
  std::vector<double> scratch_, sums_;
  std::size_t last_limit_size_ = 0;
};

extern template class Wfg<double>;
extern template class Wfg<long double>;

}  // namespace mtcs::opt::detail
