#pragma once
// SMS-EMOA's selection, kept between steps: the non-dominated rank of every member (its front),
// updated when one point comes in and when one goes out, instead of sorting all points again.
// The member it removes is the one the full sort (Deb's fast non-dominated sorting, then the
// paper's rules) removes, ties included: tests/opt/sms_fronts_test.cpp holds that sort as the
// reference. Flat buffers, reused: no allocation per step once the population has its size.

#include <cstddef>
#include <vector>

#include "mtcs/opt/hypervolume.h"
#include "mtcs/opt/population.h"
#include "kept_contributions3d.h"

namespace mtcs::opt::detail {

class SteadyStateFronts {
 public:
  std::size_t size() const { return rank_.size(); }
  void clear() { *this = SteadyStateFronts(); }
  // Whether the kept points are exactly these scores, in this order (the population this state
  // belongs to: a resumed run or migrants change it).
  bool holds(const std::vector<Individual>& population) const;
  // Appends a point: its raw score (to recognise the population) and the score it is ranked by.
  // O(n) dominance tests, plus the members whose front it pushes back.
  void push(const Score& raw, const Score& ranked);
  // The member SMS-EMOA removes: one of the worst front; the largest violation if that front is
  // infeasible; else, with `domcount_then_hv` and a front after the first, those dominated by
  // most members, then the least exclusive hypervolume against `ref`. Ties go to the first in the
  // full sort's order.
  std::size_t worst(bool domcount_then_hv, const Point& ref);
  // Removes the member worst() named (a member of the worst front: nobody's front changes).
  void erase(std::size_t i);
  // The kept 3-D contributions of the first front (the tests check they are used).
  const KeptContributions3& kept() const { return kept_; }
  long kept_picks() const { return kept_picks_; }  // removals the kept contributions decided

 private:
  bool dominates(std::size_t a, std::size_t b) const;
  // 1: a dominates b, -1: b dominates a, 0: neither.
  int relation(std::size_t a, std::size_t b) const;
  // The worst front in the order Deb's sort lists it.
  void order_worst_front();
  void contributions_of_worst(const Point& ref);

  std::size_t m_ = 0;                 // objectives
  std::vector<double> raw_f_, raw_violation_, raw_value_;
  std::vector<unsigned char> raw_feasible_;
  std::vector<double> f_, violation_;  // ranked: n x m row-major, n
  std::vector<unsigned char> feasible_;
  std::vector<int> rank_;              // 0: first front
  // 3 objectives: the first front's contributions, updated point by point (kept_contributions3d.h).
  KeptContributions3 kept_;
  long kept_picks_ = 0;
  // Scratch, kept for its capacity.
  std::vector<int> new_rank_, key_;
  std::vector<std::size_t> changed_, order_, fronts_, front_start_, worst_, tied_;
  std::vector<int> count_;
  std::vector<Point> points_;
  std::vector<double> contribution_;
};

}  // namespace mtcs::opt::detail
