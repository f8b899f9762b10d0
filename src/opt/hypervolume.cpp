#include "mtcs/opt/hypervolume.h"

#include <stdexcept>

#include "wfg.h"

namespace mtcs::opt {

double hypervolume(const std::vector<Point>& points, const Point& ref) {
  if (ref.empty()) throw std::invalid_argument("hypervolume: no objectives");
  std::vector<double> rows;
  rows.reserve(points.size() * ref.size());
  for (const Point& p : points) {
    if (p.size() != ref.size()) throw std::invalid_argument("hypervolume: point and reference sizes differ");
    bool inside = true;
    for (std::size_t k = 0; k < p.size(); ++k) inside = inside && p[k] < ref[k];
    if (inside) rows.insert(rows.end(), p.begin(), p.end());
  }
  if (ref.size() == 1) {
    double lo = ref[0];
    for (const double v : rows) lo = std::min(lo, v);
    return ref[0] - lo;
  }
  return detail::Wfg<double>(ref).hypervolume(std::move(rows));
}

}  // namespace mtcs::opt
