#pragma once
// A layout's bores for CAD and viewers (`mtcs export`): VTK PolyData (ParaView), Wavefront OBJ,
// and the bores CSV; from a layout file or from a stored run's member.

#include <memory>
#include <optional>
#include <string>

#include "mtcs/mold/layout.h"
#include "mtcs/run/session.h"

namespace mtcs::report {

enum class ExportFormat { Vtp, Obj, Csv };
// "vtp", "obj", "csv"; none for anything else.
std::optional<ExportFormat> export_format(const std::string& name);

// Segments of the tube every bore is drawn as: a closed prism of this many sides around its
// hole (volume n/2 r^2 sin(2 pi/n) L).
inline constexpr int kTubeSides = 48;

// Writes the file atomically:
//  - vtp: every bore a closed tube (outward triangles), cell data circuit, bore (index in the
//    layout) and diameter (mm);
//  - obj: one object per bore, named as in the bores CSV (c0.b1), the same tubes;
//  - csv: name,circuit,segment,p0x,...,p1z,diameter,entry_face,plugged,dead_end (mold/layout_io.h).
void export_layout(const std::string& path, const mold::Layout& layout, ExportFormat format);

// The layout of a stored run's member (by rank; default 0, the best) of a stored generation
// (default the last), decoded by the run's own session. io::InputError naming the option when
// there is no such run, generation or member.
struct StoredLayout {
  std::unique_ptr<run::Session> session;
  mold::Layout layout;
  int generation = 0, member = 0;
  std::string note;  // the mold moved or was edited
};
StoredLayout stored_layout(const std::string& run_dir, std::optional<int> generation, std::optional<int> member,
                           const std::string& mold_override = "");

}  // namespace mtcs::report
