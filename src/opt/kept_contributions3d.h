#pragma once
// SMS-EMOA's first front in 3-D with each member's exclusive hypervolume contribution, kept
// between steps: a point coming in or going out changes only the contributions of the members
// whose exclusive region it touches, and only those are recomputed (an O(n) scan and one sweep
// of the points near them; a point that joins and is the next to go leaves the old values). Each member's exclusive region lies in the box from the point
// to U, U_k the least k-th coordinate of the members no worse in the other two (or the
// reference point's): a point that does not reach below U in all three cannot change it.
//
// The kept values are computed on smaller point sets than the full sweep, so they are not bit
// for bit its values; both are sums of positive box terms, each within a relative error of
// bound() of the exact contribution. least() names the member only when its value is below every
// other's by more than both errors together, which makes it the member the full sweep
// (contributions3 on the whole front, ties to the first) names too; otherwise the caller asks
// the full sweep.

#include <cstddef>
#include <vector>

#include "mtcs/opt/hypervolume.h"

namespace mtcs::opt::detail {

class KeptContributions3 {
 public:
  // f: the members' objectives, row-major n x 3, indexed as the caller numbers its members.
  bool valid() const { return valid_; }
  bool valid_for(const Point& ref) const { return valid_ && ref == ref_; }
  void invalidate() { valid_ = false; }
  // Starts over: the members in `front` (of n) hold the contributions `values` (contributions3's
  // on the whole front, in the order of `front`).
  void rebuild(const std::vector<double>& f, std::size_t n, const std::vector<std::size_t>& front,
               const std::vector<double>& values, const Point& ref);
  // Takes the full sweep's values again (they are within the bound as well).
  void refresh(const std::vector<std::size_t>& front, const std::vector<double>& values);
  // A member appended as the last row of f; joins the front or not.
  void append(const std::vector<double>& f, bool in_front);
  // Member i leaves the front (pushed back to a later one) but stays a member.
  void leave(const std::vector<double>& f, std::size_t i);
  // Member i leaves the population (f still holds its row; later members move down one).
  void erase(const std::vector<double>& f, std::size_t i);
  // The member of least contribution, when certainly the full sweep's choice.
  bool least(std::size_t& out) const;
  // Member i's kept contribution (0 outside the front), and how many were recomputed since the
  // last rebuild (the tests check both).
  double value(std::size_t i) const { return value_[i]; }
  long recomputed() const { return recomputed_; }

 private:
  void join(const std::vector<double>& f, std::size_t i);
  void update_upper(const std::vector<double>& f, std::size_t i);
  void settle(const std::vector<double>& f);  // recomputes the members in dirty_
  double bound() const;

  bool valid_ = false;
  Point ref_;
  std::vector<unsigned char> in_front_;
  std::vector<double> upper_;  // U, n x 3
  std::vector<double> value_;
  std::size_t front_size_ = 0, largest_front_ = 0;
  long recomputed_ = 0;
  std::vector<std::size_t> dirty_;
  // The state before the last member joined, while nothing else changed.
  bool undo_ = false;
  std::vector<unsigned char> saved_in_front_;
  std::vector<double> saved_upper_, saved_value_;
  std::size_t saved_front_size_ = 0;
  // Scratch, kept for its capacity.
  std::vector<Point> near_;
  Point corner_;
  std::vector<std::size_t> order_, slot_;
  std::vector<unsigned char> mark_;
  std::vector<double> out_;
};

}  // namespace mtcs::opt::detail
