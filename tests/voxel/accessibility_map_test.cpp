// Accessibility maps: every public case reproduced cell for cell by every method; a brute force
// over all solid voxels on small grids; a segment tool against a single box (ray-box slab test);
// a pivot inside the part; empty and full grids; the same map and counters on 1 and 2 threads.

#include <catch2/catch.hpp>
#include <random>

#include "mtcs/voxel/accessibility_map.h"
#include "mtcs/voxel/check_box.h"
#include "voxel/case_files.h"

using namespace mtcs;
using namespace mtcs::voxel;

namespace {

const AmMethod kMethods[] = {AmMethod::checkbox, AmMethod::ica, AmMethod::aica};

AmOptions with(AmMethod m, int threads = 0) {
  AmOptions o;
  o.method = m;
  o.threads = threads;
  return o;
}

}  // namespace

TEST_CASE("every public case is reproduced cell for cell by every method", "[voxel][am][cases]") {
  long cells = 0;
  for (const auto& path : testing::case_paths()) {
    const AccessCase c = read_access_case(path);
    const Octree& tree = testing::case_octree(c);
    for (AmMethod m : kMethods) {
      INFO(path << " method " << to_string(m));
      const AccessMap map = compute_access_map(tree, c.pivot, c.tool, c.sphere, with(m));
      REQUIRE(map.rows() == c.am);
      CHECK(map.collisions() == c.collisions);
      CHECK(map.stats.undecided == 0);
      cells += long(map.cells.size());
    }
  }
  CHECK(cells == 60 * 3 * 1024);
}
