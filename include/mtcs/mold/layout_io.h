#pragma once
// A layout as a human-editable YAML file, so that a designer can score an existing design and
// edit an optimiser's result:
//
//   circuits:
//     - diameter: 8
//       waypoints: [[0, 40, 30], [150, 40, 30], [150, 80, 30], [0, 80, 30]]
//     - diameter: 10
//       kind: baffle             # or bubbler: a blind hole, entry on a face then tip
//       waypoints: [[110, 90, 120], [110, 90, 50]]
//
// and the drilling plan as CSV and STL for CAD.

#include <string>
#include <vector>

#include "mtcs/mold/genome.h"
#include "mtcs/mold/layout.h"
#include "mtcs/mold/scene.h"

namespace mtcs::mold {

// How far a written coordinate may be snapped without refusing the layout (mm): the shop
// rounding of saved layouts.
inline constexpr double kLayoutSnap = 0.01;

// One thing the drilling plan changes in a layout as written (a coordinate snapped, a diagonal
// step drilled as axis-parallel legs), in words naming the circuit and the waypoint.
struct LayoutChange {
  int circuit = 0, waypoint = 0;
  std::string what;
};

struct WrittenLayout {
  Genome genome;                     // as written, with the snaps applied
  std::vector<LayoutChange> changes; // everything the decoder does beyond the written holes
};

// A user's layout is scored as written or refused: io::InputError (file, line, column, field)
// on bad input, diameters not in the spec's drilling.diameters, an empty layout, a circuit whose
// waypoints are all one point, and (with drilling.axis_parallel) a waypoint that leaves its
// inlet's coordinate along an axis no allowed face is drilled along by more than kLayoutSnap;
// a waypoint of a drilled circuit outside the block (beyond kLayoutSnap);
// a baffle or bubbler without drilling.baffles, or whose entry is off those faces, whose tip is
// not straight below the entry, less than a diameter deep or outside the block.
// The optimiser's genomes are not read here: mold::decode repairs them silently.
WrittenLayout read_layout(const std::string& path, const MoldSpec& spec);
// read_layout's genome; the changes are dropped (callers that show them use read_layout).
Genome load_layout(const std::string& path, const MoldSpec& spec);
void save_layout(const std::string& path, const Genome& genome);
// bores.csv: name,circuit,segment,p0x,p0y,p0z,p1x,p1y,p1z,diameter,entry_face,plugged,dead_end,insert
// (p0 the entry on the block face, p1 the far end with the drill point; dead_end in mm); the
// cylinders `mtcs clearance --cylinders` reads (name as id, diameter / 2 as r).
void save_bores_csv(const std::string& path, const Layout& layout);
// holes.csv, the shop's hole table, mm: hole,circuit,entry_x,entry_y,entry_z (on the block face),
// direction_x,direction_y,direction_z (unit, into the block),diameter,depth (entry to the drill's
// tip),entry_face,plug_x,plug_y,plug_z (the plug at the entry of a plugged hole; empty otherwise),
// insert (baffle or bubbler: the blind hole takes that insert; empty otherwise).
void save_holes_csv(const std::string& path, const Layout& layout);
// bores.stl: every hole as a closed 24-gon prism.
void save_bores_stl(const std::string& path, const Layout& layout);

}  // namespace mtcs::mold
