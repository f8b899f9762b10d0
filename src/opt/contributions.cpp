// Exclusive hypervolume contributions, every one a sum of positive terms: no cancellation, so
// a contribution of 1e-20 of the front's volume comes out as exactly as one of 0.5.

#include <algorithm>
#include <stdexcept>

#include "contributions3d.h"
#include "wfg.h"
#include "mtcs/opt/hypervolume.h"

namespace mtcs::opt {
namespace {

bool strictly_inside(const Point& p, const Point& ref) {
  if (p.size() != ref.size()) throw std::invalid_argument("contributions: point and reference sizes differ");
  for (std::size_t k = 0; k < p.size(); ++k)
    if (!(p[k] < ref[k])) return false;
  return true;
}

// 2-D, O(n log n): a staircase point p owns the rectangle between its neighbours; the points it
// alone dominates lie in that rectangle's x-range, and p's exclusive area is the part of the
// rectangle below their own staircase, summed as positive terms.
std::vector<double> contributions2(const std::vector<Point>& points, const Point& ref) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (strictly_inside(points[i], ref)) order.push_back(i);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return points[a][0] != points[b][0] ? points[a][0] < points[b][0] : points[a][1] < points[b][1];
  });
  std::vector<std::size_t> stair;  // positions in `order`
  double best_y = ref[1];
  for (std::size_t k = 0; k < order.size(); ++k)
    if (points[order[k]][1] < best_y) stair.push_back(k), best_y = points[order[k]][1];
  std::vector<double> out(points.size(), 0.0);
  for (std::size_t j = 0; j < stair.size(); ++j) {
    const std::size_t pos = stair[j];
    const Point& p = points[order[pos]];
    if (pos + 1 < order.size() && points[order[pos + 1]] == p) continue;  // a duplicate: both 0
    const std::size_t end = j + 1 < stair.size() ? stair[j + 1] : order.size();
    const double right = j + 1 < stair.size() ? points[order[end]][0] : ref[0];
    const double top = j > 0 ? points[order[stair[j - 1]]][1] : ref[1];
    double area = 0, x = p[0], h = top;
    for (std::size_t k = pos + 1; k < end; ++k) {
      const Point& q = points[order[k]];
      if (q[1] >= h) continue;  // above the secondary staircase: covers nothing new
      area += (q[0] - x) * (h - p[1]);
      x = q[0], h = q[1];
    }
    out[order[pos]] = area + (right - x) * (h - p[1]);
  }
  return out;
}

// d >= 4: slab by slab along the last coordinate, each point's exclusive (d-1)-volume among the
// points at or below the slab, times the slab's height, down to the 3-D sweep. `members` are
// sorted by coordinate d-1; the active set is kept sorted by coordinate d-2 for the level below.
void contributions_slabs(const std::vector<Point>& points, const std::vector<std::size_t>& members, const Point& ref,
                         std::size_t d, double scale, std::vector<double>& out) {
  if (d == 3) {
    detail::contributions3(points, members, ref, scale, out);
    return;
  }
  const std::size_t slab = d - 1, below = d - 2;
  // A point whose projection two others cover adds nothing to anyone's exclusive slice, now or
  // in a later slab, and leaves the active set. "Covers" is weak dominance in the projection,
  // between equal projections only the later point covering the earlier: a strict order, so a
  // covered point's coverers, if they leave in turn, leave it covered by two others still.
  const auto dominates = [&](std::size_t a, std::size_t b, bool equal_counts) {
    bool equal = true;
    for (std::size_t c = 0; c < slab; ++c) {
      if (points[a][c] > points[b][c]) return false;
      equal = equal && points[a][c] == points[b][c];
    }
    return equal_counts || !equal;
  };
  std::vector<std::size_t> active;
  std::vector<unsigned char> coverers(points.size(), 0);
  active.reserve(members.size());
  for (std::size_t k = 0; k < members.size(); ++k) {
    const std::size_t i = members[k];
    for (const std::size_t a : active)
      if (dominates(a, i, false) && ++coverers[i] == 2) break;
    if (coverers[i] < 2) {
      std::erase_if(active, [&](std::size_t a) { return dominates(i, a, true) && ++coverers[a] == 2; });
      active.insert(std::upper_bound(active.begin(), active.end(), i,
                                     [&](std::size_t a, std::size_t b) { return points[a][below] < points[b][below]; }),
                    i);
    }
    const double next = k + 1 < members.size() ? points[members[k + 1]][slab] : ref[slab];
    const double height = next - points[i][slab];
    if (height > 0) contributions_slabs(points, active, ref, d - 1, scale * height, out);
  }
}

// d >= 5: the slabs cost O(n^3 log n) and more; WFG's box minus the limit set's hypervolume is
// fast but cancels when the contribution is tiny next to the box. Summed in long double (64-bit
// significand) it keeps ~1e-12 relative down to contributions of 1e-7 of the box; smaller ones
// are recomputed by the slabs on {p} + its limit set, where p's contribution is the same and
// the set is small.
constexpr long double kCancellation = 1e-7L;

std::vector<double> contributions_wfg(const std::vector<Point>& points, const std::vector<std::size_t>& members,
                                      const Point& ref) {
  const std::size_t d = ref.size();
  std::vector<double> rows;
  rows.reserve(members.size() * d);
  for (const std::size_t i : members) rows.insert(rows.end(), points[i].begin(), points[i].end());
  detail::Wfg<long double> wfg(ref);
  std::vector<double> out(points.size(), 0.0);
  for (std::size_t k = 0; k < members.size(); ++k) {
    long double box = 0;
    const long double exclusive = wfg.exclusive(rows, k, box);
    if (exclusive > kCancellation * box) {
      out[members[k]] = double(exclusive);
      continue;
    }
    std::vector<Point> local = wfg.last_limit_set();
    local.push_back(points[members[k]]);
    std::vector<std::size_t> order(local.size());
    for (std::size_t j = 0; j < order.size(); ++j) order[j] = j;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return local[a][d - 1] < local[b][d - 1]; });
    std::vector<double> c(local.size(), 0.0);
    contributions_slabs(local, order, ref, d, 1.0, c);
    out[members[k]] = c.back();
  }
  return out;
}

}  // namespace

std::vector<double> contributions(const std::vector<Point>& points, const Point& ref) {
  const std::size_t d = ref.size();
  if (d < 2) throw std::invalid_argument("contributions: at least two objectives");
  if (d == 2) return contributions2(points, ref);
  std::vector<double> out(points.size(), 0.0);
  std::vector<std::size_t> members;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (strictly_inside(points[i], ref)) members.push_back(i);
  std::stable_sort(members.begin(), members.end(),
                   [&](std::size_t a, std::size_t b) { return points[a][d - 1] < points[b][d - 1]; });
  // Small sets: the slabs' lower overhead wins (measured: experiments/hypervolume).
  if (d >= 5 && members.size() >= 50) return contributions_wfg(points, members, ref);
  contributions_slabs(points, members, ref, d, 1.0, out);
  return out;
}

}  // namespace mtcs::opt
