#pragma once
// A cup-shaped void in a block with bores around it: the thin shell whose core the line sinks'
// void surface and the part's coupling are checked on (void_surface_test, cavity_coupling_test).

#include <memory>
#include <vector>

#include "mtcs/mesh/triangle_mesh.h"
#include "mtcs/thermal/model.h"

namespace mtcs_test {

using mtcs::thermal::Channel;
using mtcs::thermal::Setting;
using mtcs::thermal::Vec3;

// A cup-shaped void (walls `w` thick, open at the top) in a 90 x 70 x 60 mm block: the steel
// core inside it meets the rest of the block only above the rim. Heated on every face.
inline Setting cup_void_setting(double w) {
  const double x0 = 20, x1 = 70, y0 = 15, y1 = 55, z0 = 10, z1 = 40;
  auto mesh = std::make_shared<mtcs::mesh::TriangleMesh>();
  for (const double z : {z0, z1}) mesh->vertices.insert(mesh->vertices.end(), {Vec3(x0, y0, z), Vec3(x1, y0, z), Vec3(x1, y1, z), Vec3(x0, y1, z)});
  for (const double z : {z0 + w, z1})
    mesh->vertices.insert(mesh->vertices.end(), {Vec3(x0 + w, y0 + w, z), Vec3(x1 - w, y0 + w, z), Vec3(x1 - w, y1 - w, z), Vec3(x0 + w, y1 - w, z)});
  // Outward from the part: the outer bottom and sides, the inner bottom and sides (facing the
  // core), the rim.
  mesh->triangles = {{0, 2, 1},   {0, 3, 2},   {0, 1, 5},   {0, 5, 4},   {1, 2, 6},   {1, 6, 5},   {2, 3, 7},
                     {2, 7, 6},   {3, 0, 4},   {3, 4, 7},   {8, 9, 10},  {8, 10, 11}, {8, 13, 9},  {8, 12, 13},
                     {9, 14, 10}, {9, 13, 14}, {10, 15, 11}, {10, 14, 15}, {11, 12, 8}, {11, 15, 12}, {4, 5, 13},
                     {4, 13, 12}, {5, 6, 14}, {5, 14, 13}, {6, 7, 15}, {6, 15, 14}, {7, 4, 12}, {7, 12, 15}};
  Setting s;
  s.block = {Vec3(0, 0, 0), Vec3(90, 70, 60)};
  s.conductivity = 0.03;
  for (auto& f : s.faces) f = {1e-5, 25};
  for (std::size_t t = 0; t < mesh->triangles.size(); ++t)  // seen from the void: reversed
    s.heat_in.push_back({mesh->corner(t, 0), mesh->corner(t, 2), mesh->corner(t, 1), 0.03});
  s.cavity_mesh = mesh;
  return s;
}

// Two bores under cup_void_setting's floor, two beside its walls at mid-height.
inline std::vector<Channel> cup_bores() {
  return {{mtcs::geometry::Segment{Vec3(0, 28, 4), Vec3(90, 28, 4)}, 3, 40},
          {mtcs::geometry::Segment{Vec3(0, 42, 4), Vec3(90, 42, 4)}, 3, 40},
          {mtcs::geometry::Segment{Vec3(0, 8, 25), Vec3(90, 8, 25)}, 3, 40},
          {mtcs::geometry::Segment{Vec3(0, 62, 25), Vec3(90, 62, 25)}, 3, 40}};
}

}  // namespace mtcs_test
