#pragma once
// The report a mold designer opens (issue 13): one self-contained HTML page of a stored run —
// the 3-D view of a layout in its block (part, keep-outs, bores by circuit, violated clearances
// at their place, the cavity temperature), the Pareto front of a generation whose points load
// their layout, and the run's convergence. Everything the page shows is read from the run store
// and re-derived by the run's own session (as `mtcs replay` does).

#include <optional>
#include <string>

namespace mtcs::report {

struct ReportOptions {
  std::optional<int> generation;  // the stored generation whose population is shown (default: the last)
  std::optional<int> member;      // its member shown first, by rank (default: the best, run::best_rank)
  std::string mold;               // the run's mold at a new place (as replay --mold)
  bool temperature = true;        // the cavity temperature of the member shown first (one solve)
  bool drilling_maps = true;      // the drilling maps of its bore entries (drilling_maps.h)
};

struct RunReport {
  std::string html;          // the page
  int generation = 0;
  int member = 0;
  std::size_t members = 0;   // layouts on the page (the generation's population)
  std::size_t front = 0;     // points of the feasible non-dominated front (equal members count once)
  std::size_t generations = 0;  // in the convergence charts
  std::size_t bores = 0;     // of the member shown first
  bool temperature = false;  // the page has a temperature field
  std::size_t drilling_maps = 0;  // bore entries with a drilling map on the page
  double drilling_seconds = 0;    // voxelising the part and computing those maps
  std::string note;          // what to tell the user about the mold (moved, edited)
};

// Reads RUN_DIR/run.sqlite. io::InputError (naming the file and the option) for a folder with no
// run, a test-problem run, a generation or member that is not stored.
RunReport run_report(const std::string& run_dir, const ReportOptions& options = {});

}  // namespace mtcs::report
