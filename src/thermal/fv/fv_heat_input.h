#pragma once
// Where the heat of heat_in enters the grid: on a block face, the face cells each triangle
// overlaps (exact area); elsewhere (the walls of a cavity void), the steel cells it crosses.
// Private to src/thermal.

#include <vector>

#include "thermal/fv/fv_grid.h"

namespace mtcs::thermal::fv {

// The part's film from a steel cell to the part's temperature (the coupled cavity condition):
// the film's area in the cell, in series with the conduction from the cell's centre to the wall.
struct PartFilm {
  std::size_t cell;
  double conductance;  // W/K
  double temperature;  // degrees C
  int face = -1;       // a block face's patch: the face (BlockFace order) and its face cell
  std::size_t face_cell = 0;
};

class HeatInput {
 public:
  // Fills field.face_heat and field.face_covered, `source` (W per cell) for the fixed flux that
  // enters off the block faces, and the films of the triangles with one. Throws
  // std::invalid_argument on a non-finite triangle or heat with no steel near.
  HeatInput(const Model& model, const Grid& grid, FvField& field, std::vector<double>& source);
  double total() const { return total_; }  // W, the fixed flux's part inside the block
  const std::vector<PartFilm>& films() const { return films_; }

 private:
  int block_face_of(const HeatedTriangle& t, const Box& block) const;  // -1: none
  void spread_on_face(const HeatedTriangle& t, int face);
  void spread_in_volume(const HeatedTriangle& t);
  // Into the steel cell nearest p: `heat` W, and a film of `area` mm^2 (when t has one).
  void deposit(const Vec3& p, double heat, double area, const HeatedTriangle& t, const Vec3& normal);
  void add_film(std::size_t cell, double area, double distance, const HeatedTriangle& t);

  const Grid& grid_;
  FvField& field_;
  std::vector<double>& source_;
  double tolerance_ = 0;
  double conductivity_ = 0;
  double total_ = 0;
  std::vector<PartFilm> films_;
};

}  // namespace mtcs::thermal::fv
