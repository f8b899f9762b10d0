#pragma once
// The far field of a channel's elements: each element as a point multipole at its midpoint (the
// line source's charge and quadrupole, the line dipole's moment and its s^2 correction). Used for
// the pair blocks' image points far from the source channel (line_sink_channel.cpp), where the
// exact segment kernel's logarithm and per-node roots cost more than the field is worth.

#include <cstddef>

#include "line_sink_fields.h"

namespace mtcs::thermal {

// As element_fields_float_slots (the slot layout of PointSet::make_slots: point j of target t at
// j * targets + t, weight w there; out[c * targets + t] += the weighted sum over the slots,
// points relative to `origin`), from the expansion in L / r about each element's midpoint:
//   sink    L / r + L^3 / 24 (3 tau^2 / r^5 - 1 / r^3)
//   dipole  (d . n) (L / r^3 + L^3 / 24 (15 tau^2 / r^7 - 3 / r^5))
// d = point - midpoint, r = |d|, tau = d . u. The first term left out is relatively
// ~(L / r)^4 / 50 for the sink, ~(L / r)^4 / 5 for the dipoles.
void element_far_fields_float_slots(const ChannelAxis& axis, const Vec3& origin, int kinds, const float* x,
                                    const float* y, const float* z, const float* w, std::size_t targets, int slots,
                                    float* out);

}  // namespace mtcs::thermal
