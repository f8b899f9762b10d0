#pragma once
// Where the heat of heat_in enters the grid: on a block face, the face cells each triangle
// overlaps (exact area); elsewhere (the walls of a cavity void), the steel cells it crosses.
// Private to src/thermal.

#include <vector>

#include "fv_grid.h"

namespace mtcs::thermal::fv {

class HeatInput {
 public:
  // Fills field.face_heat and field.face_covered, and `source` (W per cell) for the heat that
  // enters off the block faces. Throws std::invalid_argument on a non-finite triangle or heat
  // with no steel near.
  HeatInput(const Model& model, const Grid& grid, FvField& field, std::vector<double>& source);
  double total() const { return total_; }  // W, the part of heat_in inside the block

 private:
  int block_face_of(const HeatedTriangle& t, const Box& block) const;  // -1: none
  void spread_on_face(const HeatedTriangle& t, int face);
  void spread_in_volume(const Vec3& a, const Vec3& b, const Vec3& c, double flux);
  void deposit(const Vec3& p, double heat);  // into the steel cell nearest p

  const Grid& grid_;
  FvField& field_;
  std::vector<double>& source_;
  double tolerance_ = 0;
  double total_ = 0;
};

}  // namespace mtcs::thermal::fv
