#pragma once
// A layout as a human-editable YAML file, so that a designer can score an existing design and
// edit an optimiser's result:
//
//   circuits:
//     - diameter: 8
//       waypoints: [[0, 40, 30], [150, 40, 30], [150, 80, 30], [0, 80, 30]]
//
// and the drilling plan as CSV and STL for CAD.

#include <string>

#include "mtcs/mold/genome.h"
#include "mtcs/mold/layout.h"
#include "mtcs/mold/scene.h"

namespace mtcs::mold {

// Throws io::InputError (file, line, column, field) on bad input; diameters must be in the
// spec's drilling.diameters.
Genome load_layout(const std::string& path, const MoldSpec& spec);
void save_layout(const std::string& path, const Genome& genome);
// bores.csv: name,circuit,segment,p0x,p0y,p0z,p1x,p1y,p1z,diameter,entry_face,plugged,dead_end
// (p0 the entry on the block face, p1 the far end with the drill point; dead_end in mm); the
// cylinders `mtcs clearance --cylinders` reads (name as id, diameter / 2 as r).
void save_bores_csv(const std::string& path, const Layout& layout);
// holes.csv, the shop's hole table, mm: hole,circuit,entry_x,entry_y,entry_z (on the block face),
// direction_x,direction_y,direction_z (unit, into the block),diameter,depth (entry to the drill's
// tip),entry_face,plug_x,plug_y,plug_z (the plug at the entry of a plugged hole; empty otherwise).
void save_holes_csv(const std::string& path, const Layout& layout);
// bores.stl: every hole as a closed 24-gon prism.
void save_bores_stl(const std::string& path, const Layout& layout);

}  // namespace mtcs::mold
