#pragma once
// The sample a layout cools worst: the largest over samples of the smallest over flow bores of
// (axis distance - radius), worst_covered's e_i, the first of equals. The reach move lays a
// circuit beside it (src/run/reach_move.h).
//
// The samples are screened in single precision, tile by tile as the thermal stage scores them
// (src/eval/tiled_samples.h); only those within the screen's rounding bound of its maximum are
// scored again in double precision. So the sample and its distance are the plain double loop's,
// bit for bit (tests/eval/worst_covered_test.cpp), at a small part of its cost.

#include <memory>
#include <vector>

#include "mtcs/geometry/primitives.h"
#include "mtcs/mold/layout.h"

namespace mtcs::eval {

struct WorstSample {
  geometry::Vec3 point = geometry::Vec3::Zero();
  double wall_distance = 0;  // to the nearest flow bore: axis distance minus radius (mm)
  bool any = false;          // false: no samples
};

class WorstCoveredSearch {
 public:
  // `origin`: a corner of the block (the screen's coordinates are relative to it).
  WorstCoveredSearch(std::vector<geometry::Vec3> samples, const geometry::Vec3& origin);
  ~WorstCoveredSearch();
  WorstCoveredSearch(WorstCoveredSearch&&) noexcept;
  WorstCoveredSearch& operator=(WorstCoveredSearch&&) noexcept;

  // Without bores every sample is at infinity and the first is taken.
  WorstSample find(const mold::Layout& layout) const;
  bool empty() const { return samples_.empty(); }

 private:
  WorstSample search(const mold::Layout& layout) const;
  struct Tiles;
  std::vector<geometry::Vec3> samples_;
  geometry::Vec3 origin_;
  double sample_scale_ = 0;  // the largest |coordinate| of a sample relative to origin_
  std::unique_ptr<Tiles> tiles_;
};

}  // namespace mtcs::eval
