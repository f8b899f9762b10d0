#pragma once
// The 3-D all-contributions sweep, shared by the 3-D case and the slabs of 4-D and up.

#include <cstddef>
#include <vector>

#include "mtcs/opt/hypervolume.h"

namespace mtcs::opt::detail {

// Adds `scale` times the exclusive 3-D contribution (first three coordinates, against the first
// three of ref) of each listed point to out[index]. `members`: indices into points of points
// strictly inside the reference box, sorted by the third coordinate.
void contributions3(const std::vector<Point>& points, const std::vector<std::size_t>& members, const Point& ref,
                    double scale, std::vector<double>& out);

}  // namespace mtcs::opt::detail
