#pragma once
// Steady, cycle-averaged heat conduction in the mold steel: the problem every thermal tier
// solves (T1/T2/T2d line sinks, T3 finite volumes). Plain data, built by eval from a scene and
// a layout, or by hand in tests.
//
// The equations, the cavity condition and how each tier is checked: docs/thermal-model.md.
//
// Units everywhere in this module: mm, W, degrees C. Conductivity W/(mm K), film coefficients
// W/(mm^2 K), heat fluxes W/mm^2 (the SI values divided by 1e3, 1e6 and 1e6).

#include <array>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include "mtcs/geometry/primitives.h"
#include "mtcs/geometry/triangle_distance.h"
#include "mtcs/mesh/triangle_mesh.h"

namespace mtcs::thermal {

using geometry::Box;
using geometry::Vec3;

// The block's faces, in this order: -x, +x, -y, +y, -z, +z.
enum class BlockFace { NegX, PosX, NegY, PosY, NegZ, PosZ };

// Convection from an outer face to the air; film 0 is adiabatic (parting plane, symmetry).
struct FaceCondition {
  double film = 0;      // W/(mm^2 K)
  double ambient = 25;  // degrees C
};

// Heat entering the steel through a planar triangle of the cavity surface (cycle-averaged):
// flux + film (part_temperature - T_wall), a fixed flux and the part's response to the wall
// (eval/part_coupling.h). With film > 0 no steel can run hotter than the hottest
// part_temperature (the maximum principle), whatever the layout.
struct HeatedTriangle {
  Vec3 a, b, c;                 // counter-clockwise seen from the heat's side (the melt)
  double flux = 0;              // W/mm^2 into the steel
  double film = 0;              // W/(mm^2 K)
  double part_temperature = 0;  // degrees C
  bool heats() const { return flux != 0 || film > 0; }
};

// The flowed part of a bore: a wall at the coolant temperature (film infinite: the Dirichlet
// limit) or with a film coefficient to the coolant (Robin).
struct Channel {
  geometry::Segment axis;
  double radius = 0;
  double coolant = 40;  // degrees C: at the circuit's inlet when the coolant warms along it
  double film = std::numeric_limits<double>::infinity();  // W/(mm^2 K)
  // The coolant warms along its circuit (capacity > 0): the channels of one circuit in flow
  // order by position, each flowed from axis.p0 to p1; capacity = rho Q c_p, W/K.
  int circuit = -1;
  double position = 0;
  double capacity = 0;
};

// What does not change with the layout: the block, its faces, the heat input and the cavity.
// Where heat_in covers a block face (a patch), that part of the face touches the melt, not the
// air: it takes the flux and does not convect; the rest of the face has its FaceCondition.
struct Setting {
  Box block;
  double conductivity = 0.03;             // W/(mm K): tool steel ~ 30 W/(m K)
  std::array<FaceCondition, 6> faces{};   // by BlockFace
  std::vector<HeatedTriangle> heat_in;    // on the cavity surface or on a block face
  // The cavity as a void in the steel (T3 removes it from the grid; line sinks ignore it).
  // A patch on a block face (the reference block) has neither.
  std::optional<Box> cavity_box;
  std::shared_ptr<const mesh::TriangleMesh> cavity_mesh;
};

struct Model {
  Setting setting;
  std::vector<Channel> channels;
};

// Points of the cavity surface where temperatures are wanted, with area weights (mm^2).
struct Samples {
  std::vector<Vec3> points;
  std::vector<double> weights;
  std::vector<Vec3> normals;  // unit, out of the part into the steel; empty or 0 where unknown
  std::vector<double> thickness;  // mm, the part's wall at each sample; empty: one for all
  std::size_t size() const { return points.size(); }
};

// Area-weighted statistics of a temperature field at the samples.
struct Summary {
  double mean = 0, std = 0, max = 0;  // degrees C, K, degrees C
  std::size_t hottest = 0;            // index of the hottest sample
};
Summary summarize(const std::vector<double>& temperature, const Samples& samples);

}  // namespace mtcs::thermal
