#pragma once
// CheckBox: the exact verdict of a tool (closed solid cylinders about one direction from the
// pivot) against a closed axis-aligned box; touching counts as a collision.
//
// Certified margin: the test runs in double with a running error bound on every compared
// quantity (each operation adds |result| * 2^-53 to the propagated bound). A comparison whose
// two sides differ by more than the bound is decided; when any comparison a verdict rests on is
// closer than that, the whole test reruns in binary128 (bound |result| * 2^-113), and when even
// that cannot separate the sides (an exact touch, or a gap below ~1e-30 of the coordinates) the
// verdict is collision and counted as undecided. For inputs of magnitude S the double bound is a
// few 1e-16 S; the quad one a few 1e-34 S.
//
// Method: a cylinder C (axis segment s from the pivot, radius r, slab of the end planes) meets a
// box B iff (A) the axis segment meets B, or (B) a box edge, clipped to the slab, comes within r
// of the axis line, or (C) an end disk meets a box face inside the face: if none holds, the
// nearest point of B n slab to the axis line would lie inside a face of that polytope, where the
// distance to a line has no minimum unless the line crosses it. An axis-aligned bounding box of
// C rejects most far boxes first.

#include <cstdint>

#include "mtcs/geometry/triangle_distance.h"
#include "mtcs/voxel/tool.h"

namespace mtcs::voxel {

using geometry::Box;

enum class Precision : std::uint8_t {
  double_precision,  // decided in double
  quad_precision,    // decided in binary128
  undecided,         // closer than the binary128 bound: reported as a collision
};

struct BoxVerdict {
  bool collision = false;
  Precision precision = Precision::double_precision;
};

// The test for one pivot, direction and tool, against any number of boxes. `direction` need
// not be a unit vector; its normalisation is part of the certified error.
class CheckBox {
 public:
  CheckBox(const Vec3& pivot, const Vec3& direction, const Tool& tool);

  BoxVerdict operator()(const Box& box) const;

 private:
  Vec3 pivot_;
  Vec3 direction_;
  const Tool* tool_;
  // Double-precision preparation shared by all boxes: unit direction, 1 - d_k^2 and the
  // cylinder's half extent per unit radius along each axis, each with its error bound.
  double d_[3], d_err_[3], a_[3], a_err_[3], ext_[3], ext_err_[3];
};

}  // namespace mtcs::voxel
