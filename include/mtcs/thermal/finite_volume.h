#pragma once
// T3, the finite-volume reference: cell-centred finite volumes on a uniform grid over the block,
// the truth every thermal proxy is judged by.
//
// Discretisation (experiments/thermal/fv.md has the measured accuracy and cost):
// - n = round(L / cell) cells per axis, so the grid covers the block exactly (the spacing may
//   differ slightly per axis). A cell is steel unless its centre lies in a channel or the cavity.
// - A link from a steel cell's centre that enters a bore (towards a neighbour, or towards the
//   block face) is cut at the exact distance d to the bore wall along the grid line: Dirichlet
//   there (conductance k A / d), or the film in series (A / (d / k + 1 / (film |n.e|)), n the
//   wall's normal, e the link's direction). The symmetric scheme of Gibou, Fedkiw, Cheng and
//   Kang (J. Comput. Phys. 176, 2002): first order locally, second order in T (measured).
// - Outer faces: film to ambient with the half-cell resistance in series; a face cell carries
//   the heat of the heat_in triangles that overlap it (exact area overlap), and only its
//   uncovered part convects (the covered part touches the melt, not the air).
// - heat_in triangles that do not lie on a block face (the walls of a cavity void) heat the
//   steel cells they cross by the exact area inside each; a part inside a cavity cell goes to
//   the nearest steel cell. The void itself is a staircase of cells: first order there.
// - A triangle's film (the part's coupling) links the same cells to its part temperature: the
//   area in the cell over 1 / film + d / k, d the distance from the cell's centre to the wall
//   (half a cell on a block face). Still symmetric positive definite.
// - Symmetric positive definite system; Eigen's conjugate gradient with an incomplete Cholesky
//   preconditioner. Deterministic.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <unordered_map>
#include <vector>

#include "mtcs/thermal/model.h"

namespace mtcs::thermal {

// Incomplete Cholesky in natural order (AMD order measured 5-9x slower), or Jacobi: 2.7x the
// iterations at a third to a half of the cost each; on the reference block the two are too
// close to call on a loaded 2-core machine (experiments/thermal/fv.md).
enum class FvPreconditioner { IncompleteCholesky, Jacobi };

struct FvOptions {
  double cell = 2.0;         // mm, the target cell size
  double tolerance = 1e-10;  // relative residual |r| / |b| of the conjugate gradient
  int max_iterations = 20000;
  FvPreconditioner preconditioner = FvPreconditioner::IncompleteCholesky;
};

// The cells along a block edge of `length` mm at the target `cell` (the grid's spacing is then
// length / cells: at most half a cell off the target).
inline double fv_cells_along(double length, double cell) { return std::max(1.0, std::round(length / cell)); }

// The solved temperature field, kept so that a writer can colour a surface.
class FvField {
 public:
  std::array<int, 3> cells{};  // per axis
  Vec3 origin = Vec3::Zero();  // the block's min corner
  Vec3 spacing = Vec3::Ones();
  // Per cell (x fastest): what the cell is (kSteel, kCavity, or the index of the channel its
  // centre lies in) and its temperature (the coolant's in a channel, NaN in the cavity).
  static constexpr int kSteel = -1, kCavity = -2;
  std::vector<int> kind;
  std::vector<double> temperature;

  std::size_t index(int i, int j, int k) const {
    return std::size_t(i) + std::size_t(cells[0]) * (std::size_t(j) + std::size_t(cells[1]) * std::size_t(k));
  }
  Vec3 centre(int i, int j, int k) const;
  bool is_steel(int i, int j, int k) const;

  // Temperature at p. On a block face: the adjacent cells extrapolated to the face with the
  // face's flux and film, interpolated bilinearly along the face. Elsewhere: trilinear over the
  // surrounding cells. Cells in a channel count at the coolant's temperature (the wall is
  // within the cell), cavity cells not at all, and a cell heated from the cavity adds its
  // wall flux over the distance to p (at most half a cell): first order there, the staircase.
  // NaN when no steel cell is near.
  double temperature_at(const Vec3& p) const;

  // What the extrapolation to a face needs. Per block face (BlockFace order), per face cell
  // (first in-plane axis fastest; the in-plane axes of the face normal to a are a+1, a+2 mod 3):
  // heat entering (W) and the area covered by heat_in (mm^2).
  double conductivity = 0;
  std::array<FaceCondition, 6> faces{};
  std::array<std::vector<double>, 6> face_heat, face_covered;
  // Per steel cell next to the cavity that takes heat_in: that heat over the area of its faces
  // to the cavity (W/mm^2), to extrapolate from the centre to the cavity wall.
  std::unordered_map<std::size_t, double> wall_flux;

 private:
  double face_temperature(int face, int b, int c) const;  // of the boundary cell under face cell (b, c)
  double interior_temperature(const Vec3& p) const;
};

struct FvResult {
  std::vector<double> temperature;      // at the samples
  double heat_in = 0;                   // W, from heat_in (the part inside the block; films included)
  double heat_to_channels = 0;          // W, through the bore walls
  double heat_to_faces = 0;             // W, convected from the outer faces
  std::vector<double> heat_to_channel;  // W, per channel
  int iterations = 0;
  double residual = 0;        // relative, as the solver reports it
  bool converged = false;     // the residual reached the tolerance within max_iterations
  int coolant_solves = 1;     // solves of the coolant's warming along its circuits (a fixed point)
  double seconds = 0;         // wall time of the whole solve
  double solver_seconds = 0;  // of which the preconditioner and the iterations
  std::size_t steel_cells = 0;
  FvField field;
};

// Throws std::invalid_argument when the model or the options cannot be solved: an empty block,
// a non-positive cell, conductivity, bore radius or bore film, a negative face film, non-finite
// input, no steel cell, heat_in with no steel near. A solve cut short by max_iterations returns
// with converged = false. Channels whose coolant warms (Channel::capacity) have each its mean
// coolant along the bore: a fixed point of a few solves (coolant_solves).
FvResult solve_finite_volume(const Model& model, const Samples& samples, const FvOptions& options = {});

}  // namespace mtcs::thermal
