#pragma once
// What a designer waits for on a mold with a part (mtcs bench part).

#include <cstdint>
#include <string>
#include <vector>

namespace mtcs::bench {

struct PartBenchOptions {
  std::string mold, layout;               // layout: default the mold's own MOLD.layout.yaml
  std::vector<std::string> peers;         // other mtcs binaries whose commands run in the same run
  int children = 200, randoms = 40;       // layouts timed per rate
  int repeat = 1;                         // runs of each command (the median)
  bool optimize = false;                  // also the default mtcs optimize's wall time
  std::uint64_t seed = 1;
};

// Rows of mold,program,measure,value,unit on stdout:
// - per program (this mtcs and each peer), as a user runs them (a process each, the cache in a
//   fresh folder): evaluate_cold, evaluate_warm, thermal_cold, thermal_warm (s, wall; cold: an
//   empty cache folder, warm: the folder the cold run filled) and their peak memory (MB, the
//   largest resident set); with --optimize the default `mtcs optimize --seed 1` (s, MB);
// - in this process, on one thread with the cache warm: first_layout (s, the session and the
//   first score of the layout), child (per s: children of the optimiser's mutations of the
//   layout, scored after it), random (per s: random layouts of 3 circuits of 5 legs), and its
//   peak memory.
int bench_part(const PartBenchOptions& options);

}  // namespace mtcs::bench
