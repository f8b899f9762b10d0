#pragma once
// Hypervolume of a set of points (minimisation) against a reference point, and every point's
// exclusive contribution. d = 2: one sort and a sweep; d = 3: the dimension sweep over a 2-D
// staircase, O(n log n); d >= 4: WFG (While, Bradstreet & Barone 2012), slicing down to the 3-D
// sweep. Points that do not strictly dominate the reference point add nothing.

#include <vector>

namespace mtcs::opt {

using Point = std::vector<double>;

double hypervolume(const std::vector<Point>& points, const Point& ref);

// Exclusive contributions HV(S) - HV(S \ {p}), in input order: 0 for a point weakly dominated by
// another (duplicates included) or on the reference boundary. d = 2: a staircase sweep,
// O(n log n); d = 3: a sweep along z keeping each point's exclusive slice as boxes, O(n log n);
// d = 4: slab by slab along the last objective over the 3-D sweep, O(n^2 log n). All sums of
// positive terms, exact to rounding however small. d >= 5: WFG's box minus the limit set's
// hypervolume, recomputed by the slabs where that would cancel (relative error <~ 1e-12).
std::vector<double> contributions(const std::vector<Point>& points, const Point& ref);

}  // namespace mtcs::opt
