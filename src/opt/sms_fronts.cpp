#include "sms_fronts.h"

#include <algorithm>

#include "contributions3d.h"

namespace mtcs::opt::detail {

bool SteadyStateFronts::holds(const std::vector<Individual>& population) const {
  if (population.size() != size()) return false;
  for (std::size_t i = 0; i < population.size(); ++i) {
    const Score& s = population[i].score;
    if (s.objectives.size() != m_ || (s.feasible ? 1 : 0) != raw_feasible_[i] || s.violation != raw_violation_[i] ||
        s.value != raw_value_[i] || !std::equal(s.objectives.begin(), s.objectives.end(), raw_f_.begin() + long(i * m_)))
      return false;
  }
  return true;
}

// Constrained domination: feasible beats infeasible, less violation beats more, then Pareto.
bool SteadyStateFronts::dominates(std::size_t a, std::size_t b) const {
  if (feasible_[a] != feasible_[b]) return feasible_[a] != 0;
  if (!feasible_[a]) return violation_[a] < violation_[b];
  const double* fa = &f_[a * m_];
  const double* fb = &f_[b * m_];
  bool strictly = false;
  for (std::size_t k = 0; k < m_; ++k) {
    if (fa[k] > fb[k]) return false;
    strictly = strictly || fa[k] < fb[k];
  }
  return strictly;
}

int SteadyStateFronts::relation(std::size_t a, std::size_t b) const {
  if (feasible_[a] != feasible_[b]) return feasible_[a] ? 1 : -1;
  if (!feasible_[a]) return violation_[a] < violation_[b] ? 1 : violation_[b] < violation_[a] ? -1 : 0;
  const double* fa = &f_[a * m_];
  const double* fb = &f_[b * m_];
  bool a_better = false, b_better = false;
  for (std::size_t k = 0; k < m_; ++k) {
    a_better = a_better || fa[k] < fb[k];
    b_better = b_better || fb[k] < fa[k];
  }
  return a_better == b_better ? 0 : a_better ? 1 : -1;
}

void SteadyStateFronts::push(const Score& raw, const Score& ranked) {
  if (size() == 0) m_ = ranked.objectives.size();
  raw_f_.insert(raw_f_.end(), raw.objectives.begin(), raw.objectives.end());
  raw_violation_.push_back(raw.violation);
  raw_value_.push_back(raw.value);
  raw_feasible_.push_back(raw.feasible ? 1 : 0);
  f_.insert(f_.end(), ranked.objectives.begin(), ranked.objectives.end());
  violation_.push_back(ranked.violation);
  feasible_.push_back(ranked.feasible ? 1 : 0);
  const std::size_t n = size();  // the new point's index (rank_ has not grown yet)
  // Its front: one after the deepest of its dominators'.
  int r = 0;
  bool pushes_back = false;
  for (std::size_t q = 0; q < n; ++q) {
    const int rel = relation(q, n);
    if (rel > 0) r = std::max(r, rank_[q] + 1);
    pushes_back = pushes_back || rel < 0;
  }
  rank_.push_back(r);
  if (kept_.valid()) kept_.append(f_, r == 0);
  if (!pushes_back) return;
  // Members it dominates, and theirs in turn, may move to later fronts. A member's dominators
  // all had smaller ranks, so visiting the old members by rank settles each one's dominators
  // first; only the members that moved can move others.
  int deepest = 0;
  for (std::size_t q = 0; q < n; ++q) deepest = std::max(deepest, rank_[q]);
  front_start_.assign(std::size_t(deepest) + 2, 0);
  for (std::size_t q = 0; q < n; ++q) ++front_start_[std::size_t(rank_[q]) + 1];
  for (std::size_t k = 1; k < front_start_.size(); ++k) front_start_[k] += front_start_[k - 1];
  order_.resize(n);
  for (std::size_t q = 0; q < n; ++q) order_[front_start_[std::size_t(rank_[q])]++] = q;
  new_rank_.assign(rank_.begin(), rank_.end());
  changed_.assign(1, n);
  for (const std::size_t q : order_) {
    int nr = rank_[q];
    for (const std::size_t c : changed_)
      if (new_rank_[c] + 1 > nr && dominates(c, q)) nr = new_rank_[c] + 1;
    if (nr != rank_[q]) new_rank_[q] = nr, changed_.push_back(q);
  }
  if (kept_.valid()) {  // members pushed out of the first front leave it; many: start over when needed
    const auto leaving = std::count_if(changed_.begin() + 1, changed_.end(), [&](std::size_t q) { return rank_[q] == 0; });
    if (leaving > 8) kept_.invalidate();
    else
      for (auto q = changed_.begin() + 1; q != changed_.end(); ++q)
        if (rank_[*q] == 0) kept_.leave(f_, *q);
  }
  rank_.assign(new_rank_.begin(), new_rank_.end());
}

// Deb's sort lists the first front by index, and each later front as its members' last
// dominator in the front before is visited: by that dominator's position there, then by index.
void SteadyStateFronts::order_worst_front() {
  const std::size_t n = size();
  const int deepest = rank_[worst_.front()];
  front_start_.assign(std::size_t(deepest) + 2, 0);
  for (std::size_t q = 0; q < n; ++q) ++front_start_[std::size_t(rank_[q]) + 1];
  for (std::size_t k = 1; k < front_start_.size(); ++k) front_start_[k] += front_start_[k - 1];
  fronts_.resize(n);
  order_.assign(front_start_.begin(), front_start_.end() - 1);  // fill positions
  for (std::size_t q = 0; q < n; ++q) fronts_[order_[std::size_t(rank_[q])]++] = q;
  key_.resize(n);
  new_rank_.resize(n);  // here: position within its front
  for (std::size_t p = front_start_[0]; p < front_start_[1]; ++p) new_rank_[fronts_[p]] = int(p - front_start_[0]);
  for (std::size_t k = 1; k <= std::size_t(deepest); ++k) {
    const auto before = fronts_.begin() + long(front_start_[k - 1]);
    const auto begin = fronts_.begin() + long(front_start_[k]);
    const auto end = fronts_.begin() + long(front_start_[k + 1]);
    for (auto j = begin; j != end; ++j) {
      int last = -1;
      for (auto i = before; i != begin; ++i)
        if (new_rank_[*i] > last && dominates(*i, *j)) last = new_rank_[*i];
      key_[*j] = last;
    }
    std::stable_sort(begin, end, [&](std::size_t a, std::size_t b) { return key_[a] < key_[b]; });
    for (auto j = begin; j != end; ++j) new_rank_[*j] = int(j - begin);
  }
  worst_.assign(fronts_.begin() + long(front_start_[std::size_t(deepest)]), fronts_.begin() + long(front_start_[std::size_t(deepest) + 1]));
}

void SteadyStateFronts::contributions_of_worst(const Point& ref) {
  const std::size_t w = worst_.size();
  if (m_ != 2) {
    points_.resize(w);
    for (std::size_t k = 0; k < w; ++k) points_[k].assign(f_.begin() + long(worst_[k] * m_), f_.begin() + long((worst_[k] + 1) * m_));
    if (m_ != 3 || ref.size() != 3) {
      contribution_ = contributions(points_, ref);
      return;
    }
    // contributions() in 3-D, on kept buffers: the points strictly inside the box, stably by z.
    order_.clear();
    for (std::size_t k = 0; k < w; ++k)
      if (points_[k][0] < ref[0] && points_[k][1] < ref[1] && points_[k][2] < ref[2]) order_.push_back(k);
    std::sort(order_.begin(), order_.end(), [&](std::size_t a, std::size_t b) {  // stable: ties by index
      return points_[a][2] != points_[b][2] ? points_[a][2] < points_[b][2] : a < b;
    });
    contribution_.assign(w, 0.0);
    contributions3(points_, order_, ref, 1.0, contribution_);
    return;
  }
  // 2-D, mutually non-dominated points: sorted by x, y falls, and equal x means a duplicate. A
  // point owns the rectangle up to its neighbours, as the general sweep (contributions2) finds
  // it, in the same arithmetic; duplicates and points outside the reference box own nothing.
  const auto x = [&](std::size_t k) { return f_[worst_[k] * 2]; };
  const auto y = [&](std::size_t k) { return f_[worst_[k] * 2 + 1]; };
  order_.clear();
  for (std::size_t k = 0; k < w; ++k)
    if (x(k) < ref[0] && y(k) < ref[1]) order_.push_back(k);
  std::sort(order_.begin(), order_.end(), [&](std::size_t a, std::size_t b) { return x(a) != x(b) ? x(a) < x(b) : y(a) < y(b); });
  contribution_.assign(w, 0.0);
  const std::size_t k_end = order_.size();
  const auto same = [&](std::size_t a, std::size_t b) { return x(a) == x(b) && y(a) == y(b); };
  for (std::size_t k = 0; k < k_end; ++k) {
    const std::size_t p = order_[k];
    if ((k + 1 < k_end && same(p, order_[k + 1])) || (k > 0 && same(p, order_[k - 1]))) continue;
    const double right = k + 1 < k_end ? x(order_[k + 1]) : ref[0];
    const double top = k > 0 ? y(order_[k - 1]) : ref[1];
    contribution_[p] = 0.0 + (right - x(p)) * (top - y(p));
  }
}

std::size_t SteadyStateFronts::worst(bool domcount_then_hv, const Point& ref) {
  const std::size_t n = size();
  const int deepest = *std::max_element(rank_.begin(), rank_.end());
  worst_.clear();
  for (std::size_t q = 0; q < n; ++q)
    if (rank_[q] == deepest) worst_.push_back(q);
  if (worst_.size() == 1) return worst_.front();
  const bool first = deepest == 0;
  if (!first) order_worst_front();
  if (!feasible_[worst_.front()]) {
    std::size_t drop = worst_.front();
    for (const std::size_t i : worst_)
      if (violation_[i] > violation_[drop]) drop = i;
    return drop;
  }
  count_.assign(worst_.size(), 0);
  if (domcount_then_hv && !first)
    for (std::size_t w = 0; w < worst_.size(); ++w)
      for (std::size_t o = 0; o < n; ++o) count_[w] += dominates(o, worst_[w]) ? 1 : 0;
  const int most = *std::max_element(count_.begin(), count_.end());
  tied_.clear();
  for (std::size_t w = 0; w < worst_.size(); ++w)
    if (count_[w] == most) tied_.push_back(w);
  std::size_t w = tied_.front();
  if (tied_.size() > 1) {
    const bool kept = first && m_ == 3 && ref.size() == 3;
    std::size_t least = 0;
    if (kept && kept_.valid_for(ref) && kept_.least(least)) return ++kept_picks_, least;
    contributions_of_worst(ref);
    if (kept && kept_.valid_for(ref)) kept_.refresh(worst_, contribution_);
    else if (kept) kept_.rebuild(f_, n, worst_, contribution_, ref);
    for (const std::size_t t : tied_)
      if (contribution_[t] < contribution_[w]) w = t;
  }
  return worst_[w];
}

void SteadyStateFronts::erase(std::size_t i) {
  // A member of the worst front dominates nobody: the others keep their fronts.
  if (kept_.valid()) kept_.erase(f_, i);
  const auto row = [&](std::vector<double>& v) { v.erase(v.begin() + long(i * m_), v.begin() + long((i + 1) * m_)); };
  row(raw_f_);
  row(f_);
  raw_violation_.erase(raw_violation_.begin() + long(i));
  raw_value_.erase(raw_value_.begin() + long(i));
  raw_feasible_.erase(raw_feasible_.begin() + long(i));
  violation_.erase(violation_.begin() + long(i));
  feasible_.erase(feasible_.begin() + long(i));
  rank_.erase(rank_.begin() + long(i));
}

}  // namespace mtcs::opt::detail
