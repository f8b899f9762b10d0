#pragma once
// A loaded mold with what the queries need: the block's shape and the BVHs of its meshes,
// built only for the meshes the spec has.

#include <memory>
#include <optional>
#include <vector>

#include "mtcs/mesh/bvh.h"
#include "mtcs/mold/mold_spec.h"

namespace mtcs::mold {

// Where a ray from inside the block leaves it.
struct BlockExit {
  geometry::Vec3 point;
  geometry::Vec3 normal;  // outward
  bool hit = false;
};

class Scene {
 public:
  explicit Scene(MoldSpec spec);

  const MoldSpec& spec() const { return spec_; }
  const Box& block_bounds() const { return block_bounds_; }
  BlockExit exit_block(const geometry::Vec3& from, const geometry::Vec3& direction) const;
  // Distance from the solid cylinder to the block's surface, ignoring the first `skip` mm of
  // its axis from p0 (its entry) and the last `skip_end` mm before p1 (an open far end of a
  // through-bore). Negative when the axis leaves the block.
  double surface_clearance(const geometry::Cylinder& c, double skip, double cap, double skip_end = 0) const;
  // Where that clearance is smallest: midway between the bore's wall and the block's surface
  // (or the end of the axis that left the block). For the report of a violation, not the hot path.
  geometry::Vec3 surface_place(const geometry::Cylinder& c, double skip, double skip_end = 0) const;

  const mesh::TriangleBvh* cavity_bvh() const { return cavity_bvh_.get(); }
  // With cavity.wall_thickness: local, the part's wall thickness (mm) at each cavity mesh
  // triangle's centroid (mesh/wall_thickness.h); spec().cavity->wall_thickness is then their
  // largest, the wall that sets the cycle. Empty otherwise.
  const std::vector<double>& cavity_thickness() const { return cavity_thickness_; }
  // The part's wall thickness at a point of the cavity's surface with its normal out of the
  // part: local where the spec asks for it, else the spec's one value.
  double wall_thickness_at(const geometry::Vec3& p, const geometry::Vec3& outward) const;
  const mesh::TriangleBvh* keep_out_bvh(std::size_t k) const { return keep_out_bvh_[k].get(); }

 private:
  MoldSpec spec_;
  Box block_bounds_;
  std::unique_ptr<mesh::TriangleBvh> block_bvh_, cavity_bvh_;
  std::vector<std::unique_ptr<mesh::TriangleBvh>> keep_out_bvh_;
  std::vector<double> cavity_thickness_;
};

}  // namespace mtcs::mold
