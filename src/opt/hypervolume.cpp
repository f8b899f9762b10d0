#include "mtcs/opt/hypervolume.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <stdexcept>

namespace mtcs::opt {
namespace {

bool weakly_dominates(const Point& a, const Point& b) {
  for (std::size_t k = 0; k < a.size(); ++k)
    if (a[k] > b[k]) return false;
  return true;
}

// Points strictly inside the reference box.
std::vector<Point> inside(const std::vector<Point>& pts, const Point& ref) {
  std::vector<Point> out;
  for (const Point& p : pts) {
    if (p.size() != ref.size()) throw std::invalid_argument("hypervolume: point and reference sizes differ");
    bool in = true;
    for (std::size_t k = 0; k < p.size(); ++k) in = in && p[k] < ref[k];
    if (in) out.push_back(p);
  }
  return out;
}

double hv2(std::vector<Point> pts, const Point& ref) {
  std::sort(pts.begin(), pts.end(), [](const Point& a, const Point& b) { return a[0] != b[0] ? a[0] < b[0] : a[1] < b[1]; });
  double area = 0, best_y = ref[1];
  std::size_t i = 0;
  while (i < pts.size()) {
    if (pts[i][1] >= best_y) {
      ++i;
      continue;
    }
    // The next staircase point: the first later point with a lower y.
    std::size_t j = i + 1;
    while (j < pts.size() && pts[j][1] >= pts[i][1]) ++j;
    const double next_x = j < pts.size() ? pts[j][0] : ref[0];
    area += (next_x - pts[i][0]) * (ref[1] - pts[i][1]);
    best_y = pts[i][1];
    i = j;
  }
  return area;
}

// 3-D dimension sweep: points by increasing z; the 2-D staircase of those seen so far and its
// area, updated per insertion.
double hv3(std::vector<Point> pts, const Point& ref) {
  std::sort(pts.begin(), pts.end(), [](const Point& a, const Point& b) { return a[2] < b[2]; });
  std::map<double, double> stair;  // x -> y, x increasing, y decreasing
  double area = 0, volume = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const double x = pts[i][0], y = pts[i][1];
    auto right = stair.lower_bound(x);  // first element with x' >= x
    double top = ref[1];                // the staircase height just left of x
    if (right != stair.begin()) top = std::prev(right)->second;
    const bool covered = top <= y || (right != stair.end() && right->first == x && right->second <= y);
    if (!covered) {
      double at = x, h = top;
      while (right != stair.end() && right->second >= y) {
        area += (right->first - at) * (h - y);
        at = right->first, h = right->second;
        right = stair.erase(right);
      }
      area += ((right != stair.end() ? right->first : ref[0]) - at) * (h - y);
      stair.emplace_hint(right, x, y);
    }
    const double next_z = i + 1 < pts.size() ? pts[i + 1][2] : ref[2];
    volume += area * (next_z - pts[i][2]);
  }
  return volume;
}

double hv_any(std::vector<Point> pts, const Point& ref);

// WFG's exclusive volume of p against the points after it in a sorted list.
double exclusive(const Point& p, const std::vector<Point>& rest, const Point& ref) {
  double box = 1;
  for (std::size_t k = 0; k < p.size(); ++k) box *= ref[k] - p[k];
  std::vector<Point> limit;
  for (const Point& q : rest) {
    Point m(p.size());
    for (std::size_t k = 0; k < p.size(); ++k) m[k] = std::max(p[k], q[k]);
    limit.push_back(std::move(m));
  }
  // The 2-D and 3-D sweeps take dominated points in their stride; WFG wants the non-dominated
  // ones only (the limit set is usually tiny).
  if (p.size() <= 3) return box - hv_any(std::move(limit), ref);
  std::vector<Point> nd;
  for (std::size_t i = 0; i < limit.size(); ++i) {
    bool dominated = false;
    for (std::size_t j = 0; j < limit.size() && !dominated; ++j) {
      if (i == j) continue;
      dominated = weakly_dominates(limit[j], limit[i]) && (limit[j] != limit[i] || j < i);
    }
    if (!dominated) nd.push_back(limit[i]);
  }
  return box - hv_any(std::move(nd), ref);
}

double wfg(std::vector<Point> pts, const Point& ref) {
  // Sorting by the last objective, worst first, keeps limit sets small.
  const std::size_t d = ref.size();
  std::sort(pts.begin(), pts.end(), [d](const Point& a, const Point& b) { return a[d - 1] > b[d - 1]; });
  double sum = 0;
  for (std::size_t i = 0; i < pts.size(); ++i)
    sum += exclusive(pts[i], std::vector<Point>(pts.begin() + long(i) + 1, pts.end()), ref);
  return sum;
}

double hv_any(std::vector<Point> pts, const Point& ref) {
  if (pts.empty()) return 0;
  switch (ref.size()) {
    case 1: {
      double lo = ref[0];
      for (const Point& p : pts) lo = std::min(lo, p[0]);
      return ref[0] - lo;
    }
    case 2: return hv2(std::move(pts), ref);
    case 3: return hv3(std::move(pts), ref);
    default: return wfg(std::move(pts), ref);
  }
}

}  // namespace

double hypervolume(const std::vector<Point>& points, const Point& ref) { return hv_any(inside(points, ref), ref); }

}  // namespace mtcs::opt
