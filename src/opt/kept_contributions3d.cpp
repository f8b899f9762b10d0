#include "kept_contributions3d.h"

#include <algorithm>
#include <cfloat>
#include <limits>

#include "contributions3d.h"

namespace mtcs::opt::detail {
namespace {

const double* row(const std::vector<double>& f, std::size_t i) { return f.data() + i * 3; }

bool below(const double* q, const double* u) { return q[0] < u[0] && q[1] < u[1] && q[2] < u[2]; }

}  // namespace

// The sweep closes at most 3n + 1 box terms of a point, each within 5 roundings of its exact
// volume (three differences, two products), and sums them: relative error below (3n + 6) u.
// Sixteen times that in machine epsilon (32 u per point) leaves a wide margin.
double KeptContributions3::bound() const { return 16.0 * double(largest_front_ + 8) * DBL_EPSILON; }

void KeptContributions3::rebuild(const std::vector<double>& f, std::size_t n, const std::vector<std::size_t>& front,
                                 const std::vector<double>& values, const Point& ref) {
  ref_ = ref;
  in_front_.assign(n, 0);
  upper_.assign(n * 3, 0.0);
  value_.assign(n, 0.0);
  for (std::size_t k = 0; k < front.size(); ++k) in_front_[front[k]] = 1, value_[front[k]] = values[k];
  front_size_ = largest_front_ = front.size();
  for (const std::size_t i : front) update_upper(f, i);
  recomputed_ = 0;
  undo_ = false;
  valid_ = true;
}

void KeptContributions3::refresh(const std::vector<std::size_t>& front, const std::vector<double>& values) {
  for (std::size_t k = 0; k < front.size(); ++k) value_[front[k]] = values[k];
}

void KeptContributions3::update_upper(const std::vector<double>& f, std::size_t i) {
  double* u = &upper_[i * 3];
  std::copy(ref_.begin(), ref_.end(), u);
  const double* p = row(f, i);
  for (std::size_t r = 0; r < in_front_.size(); ++r) {
    if (!in_front_[r] || r == i) continue;
    const double* q = row(f, r);
    if (q[1] <= p[1] && q[2] <= p[2]) u[0] = std::min(u[0], q[0]);
    if (q[0] <= p[0] && q[2] <= p[2]) u[1] = std::min(u[1], q[1]);
    if (q[0] <= p[0] && q[1] <= p[1]) u[2] = std::min(u[2], q[2]);
  }
}

// The marked members' exclusive volumes in one sweep: every front member reaching below the
// largest of their boxes' far corners, with that corner as the reference point. A member's
// region lies in its own box, which every point that could cut it reaches into, so the sweep
// finds each marked member's exact region (in its own arithmetic).
void KeptContributions3::settle(const std::vector<double>& f) {
  if (dirty_.empty()) return;
  corner_.assign(3, -std::numeric_limits<double>::infinity());
  std::size_t live = 0;
  for (const std::size_t i : dirty_) {
    ++recomputed_;
    const double* u = &upper_[i * 3];
    value_[i] = 0.0;
    if (!below(row(f, i), u)) continue;  // an empty box: a duplicate, or outside the reference box
    ++live;
    for (int k = 0; k < 3; ++k) corner_[std::size_t(k)] = std::max(corner_[std::size_t(k)], u[k]);
  }
  if (live == 0) return dirty_.clear();
  std::size_t used = 0;
  for (std::size_t r = 0; r < in_front_.size(); ++r) {
    if (!in_front_[r] || !below(row(f, r), corner_.data())) continue;
    if (near_.size() == used) near_.emplace_back(3), slot_.push_back(0);
    std::copy(row(f, r), row(f, r) + 3, near_[used].begin());
    slot_[used++] = r;
  }
  order_.resize(used);
  for (std::size_t k = 0; k < used; ++k) order_[k] = k;
  std::sort(order_.begin(), order_.end(), [&](std::size_t a, std::size_t b) {
    return near_[a][2] != near_[b][2] ? near_[a][2] < near_[b][2] : a < b;
  });
  out_.assign(used, 0.0);
  contributions3(near_, order_, corner_, 1.0, out_);
  mark_.assign(in_front_.size(), 0);
  for (const std::size_t i : dirty_) mark_[i] = below(row(f, i), &upper_[i * 3]) ? 1 : 0;
  for (std::size_t k = 0; k < used; ++k)
    if (mark_[slot_[k]]) value_[slot_[k]] = out_[k];
  dirty_.clear();
}

void KeptContributions3::join(const std::vector<double>& f, std::size_t i) {
  const double* q = row(f, i);
  in_front_[i] = 1;
  for (std::size_t r = 0; r < in_front_.size(); ++r) {
    if (!in_front_[r] || r == i) continue;
    double* u = &upper_[r * 3];
    const double* p = row(f, r);
    const bool touches = below(q, u);  // reaches into r's box: may take part of its region
    if (q[1] <= p[1] && q[2] <= p[2]) u[0] = std::min(u[0], q[0]);
    if (q[0] <= p[0] && q[2] <= p[2]) u[1] = std::min(u[1], q[1]);
    if (q[0] <= p[0] && q[1] <= p[1]) u[2] = std::min(u[2], q[2]);
    if (touches) dirty_.push_back(r);
  }
  largest_front_ = std::max(largest_front_, ++front_size_);
  update_upper(f, i);
  dirty_.push_back(i);
  settle(f);
}

void KeptContributions3::leave(const std::vector<double>& f, std::size_t i) {
  undo_ = false;
  in_front_[i] = 0;
  --front_size_;
  const double* d = row(f, i);
  for (std::size_t r = 0; r < in_front_.size(); ++r) {
    if (!in_front_[r]) continue;
    const double* p = row(f, r);
    const double* u = &upper_[r * 3];
    // i may have set r's box: then it grows.
    if ((d[1] <= p[1] && d[2] <= p[2] && d[0] <= u[0]) || (d[0] <= p[0] && d[2] <= p[2] && d[1] <= u[1]) ||
        (d[0] <= p[0] && d[1] <= p[1] && d[2] <= u[2]))
      update_upper(f, r);
    // r gains what only it and i covered: inside r's (new) box, above i.
    if (below(d, u)) dirty_.push_back(r);
  }
  settle(f);
}

void KeptContributions3::append(const std::vector<double>& f, bool in_front) {
  undo_ = in_front;
  if (in_front) {  // the state without it, back as it was if it is the next to go (often)
    saved_in_front_ = in_front_;
    saved_upper_ = upper_;
    saved_value_ = value_;
    saved_front_size_ = front_size_;
  }
  in_front_.push_back(0);
  upper_.insert(upper_.end(), ref_.begin(), ref_.end());
  value_.push_back(0.0);
  if (in_front) join(f, in_front_.size() - 1);
}

void KeptContributions3::erase(const std::vector<double>& f, std::size_t i) {
  if (undo_ && i + 1 == in_front_.size()) {
    undo_ = false;
    in_front_.swap(saved_in_front_);
    upper_.swap(saved_upper_);
    value_.swap(saved_value_);
    front_size_ = saved_front_size_;
    return;
  }
  undo_ = false;
  if (in_front_[i]) leave(f, i);
  in_front_.erase(in_front_.begin() + long(i));
  upper_.erase(upper_.begin() + long(i * 3), upper_.begin() + long(i * 3 + 3));
  value_.erase(value_.begin() + long(i));
}

bool KeptContributions3::least(std::size_t& out) const {
  std::size_t a = in_front_.size();
  for (std::size_t i = 0; i < in_front_.size(); ++i)
    if (in_front_[i] && (a == in_front_.size() || value_[i] < value_[a])) a = i;
  if (a == in_front_.size()) return false;
  // Kept value v and the sweep's s are both within e of the exact value: s_a < s_b for sure when
  // v_a (1 + e)^2 < v_b (1 - e)^2, which 1 + 5e covers.
  const double limit = value_[a] * (1.0 + 5.0 * bound());
  for (std::size_t i = 0; i < in_front_.size(); ++i)
    if (in_front_[i] && i != a && !(value_[i] > limit)) return false;
  out = a;
  return true;
}

}  // namespace mtcs::opt::detail
