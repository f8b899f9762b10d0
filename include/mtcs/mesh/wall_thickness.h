#pragma once
// A molded part's local wall thickness: at a point of its closed surface, the diameter of the
// largest ball inside the part that touches the surface there (its centre on the inward normal).
// On a flat wall it is the distance straight across; at a rib's root, a corner or a boss it is
// the width of the steel-free material there, where a ray across would run along the rib.
// Cooling time grows with its square (eval/cycle_time.h), so the thickest wall sets the cycle.

#include "mtcs/mesh/bvh.h"

namespace mtcs::mesh {

// The inscribed ball's diameter at p on `part`'s surface, `outward` the surface's unit normal
// there (out of the part), at most `cap` mm; 0 only when the inward ray crosses nothing (an
// open surface). Bisection on the radius r: the ball of centre p - r outward fits while the surface
// lies at least 0.99 r from its centre (a faceted curve cuts a tangent ball at its facet edges);
// the first crossing of the inward ray bounds r by half its distance. Within 1 % (the slack)
// and 1e-4 of that bound. Where two walls of thickness s meet, the corner is up to 1.17 s thick
// (three walls: 1.27 s): the corners that cool last.
double inscribed_diameter(const TriangleBvh& part, const geometry::Vec3& p, const geometry::Vec3& outward, double cap);

}  // namespace mtcs::mesh
