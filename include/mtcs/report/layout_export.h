#pragma once
// A layout's bores for CAD and viewers (`mtcs export`): STEP AP214 solids (with the optional
// OpenCASCADE component), VTK PolyData (ParaView), Wavefront OBJ and the bores CSV; from a layout
// file or from a stored run's member.

#include <memory>
#include <optional>
#include <string>

#include "mtcs/mold/layout.h"
#include "mtcs/run/session.h"

namespace mtcs::report {

enum class ExportFormat { Step, Vtp, Obj, Csv };
// "step", "vtp", "obj", "csv"; none for anything else.
std::optional<ExportFormat> export_format(const std::string& name);

// Segments of the tube every bore is drawn as: a closed prism of this many sides around its
// hole (volume n/2 r^2 sin(2 pi/n) L).
inline constexpr int kTubeSides = 48;

// Whether this build writes STEP (CMake found OpenCASCADE: MTCS_WITH_OCCT).
bool step_available();

// Writes the file atomically:
//  - step: AP214, one named solid per bore (c0.b1): the exact cylinder of its hole, as bores.stl
//    and bores.csv give it (plain cylinders: the layout model has no drill tips); mm. Without
//    OpenCASCADE, io::InputError on --format saying how to get it;
//  - vtp: every bore a closed tube (outward triangles), cell data circuit, bore (index in the
//    layout) and diameter (mm);
//  - obj: one object per bore, named as in the bores CSV (c0.b1), the same tubes;
//  - csv: name,circuit,segment,p0x,...,p1z,diameter,entry_face,plugged,dead_end,insert (mold/layout_io.h).
void export_layout(const std::string& path, const mold::Layout& layout, ExportFormat format);

// The layout of a stored run's member (by rank; default the best, run::best_rank) of a stored generation
// (default the last), decoded by the run's own session and given as the shop receives it: the
// genome rounded by run::shop_layout, the hole ends by run::shop_plan (the best of the last
// generation is optimize's bores.csv, unless a polish improved it). io::InputError naming the
// option when there is no such run, generation or member.
struct StoredLayout {
  std::unique_ptr<run::Session> session;
  mold::Layout layout;
  int generation = 0, member = 0;
  std::string note;  // the mold moved or was edited
};
StoredLayout stored_layout(const std::string& run_dir, std::optional<int> generation, std::optional<int> member,
                           const std::string& mold_override = "");

// What `mtcs export SOURCE` exports: a stored run's member (layout_file empty) or the layout file
// of the mold spec SOURCE, its hole ends rounded as bores.csv gives them (run::shop_plan).
StoredLayout layout_to_export(const std::string& source, const std::string& layout_file, std::optional<int> generation,
                              std::optional<int> member);

// `mtcs export` below the command line: the layout above written as `format` to `out`, by default
// default_export_path. Checks the format before building anything.
struct ExportRequest {
  std::string source, layout_file, format = "vtp", out;
  std::optional<int> generation, member;
};
struct Exported {
  std::string path, note;
  std::size_t bores = 0;
};
Exported export_bores(const ExportRequest& request);

// Where `mtcs export` writes without --out: beside the layout file with the format's extension
// (best.layout.yaml -> best.layout.step), or RUN_DIR/exports/generation_G_member_K.FORMAT; never
// one of the run's own files (its bores.csv is the polished best's).
std::string default_export_path(const ExportRequest& request, const StoredLayout& layout);

}  // namespace mtcs::report
