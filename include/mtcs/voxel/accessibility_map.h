#pragma once
// Accessibility maps (Chen et al., ICPP 2019): for a tool pivoting at a point, which directions
// of a sphere grid let it touch no solid voxel. Each direction traverses the octree on its own
// (Algorithm 2): a node the tool misses is pruned, a full node it meets is a collision, a mixed
// node it meets is opened. The methods differ in the node test:
//   checkbox  exact CheckBox on every node (the baseline);
//   ica       CheckICA (inscribed / circumscribed spheres, memoised cone intervals for the top
//             levels), CheckBox on corner cases (the paper's MICA);
//   aica      CheckICA, corner cases expanded into children (full nodes and voxels into their
//             eight octants, which cover them exactly) down to `subvoxel_levels` below single
//             voxels, where CheckBox decides (the paper's AICA, one step further).
// All three give the exact map; directions run in parallel (TBB), each writing its own cell, so
// the map and the counters are the same for any thread count.

#include <cstdint>
#include <string>
#include <vector>

#include "mtcs/voxel/octree.h"
#include "mtcs/voxel/tool.h"

namespace mtcs::voxel {

enum class AmMethod { checkbox, ica, aica };

AmMethod parse_am_method(const std::string& name);  // "checkbox" | "ica" | "aica"
std::string to_string(AmMethod m);

struct AmOptions {
  AmMethod method = AmMethod::aica;
  int threads = 0;       // 0: TBB's default
  int memo_levels = 2;   // octree levels whose cone intervals are precomputed (ica, aica)
  int subvoxel_levels = 1;  // aica: corner-case voxels are split this many times before CheckBox
};

struct AmStats {
  std::uint64_t node_tests = 0;       // CheckICA or CheckBox calls on nodes
  std::uint64_t checkbox_calls = 0;   // exact box tests
  std::uint64_t quad_verdicts = 0;    // box tests decided in binary128
  std::uint64_t undecided = 0;        // box tests closer than the binary128 bound (collision)
  std::uint64_t memo_nodes = 0;       // nodes with precomputed cone intervals

  // Share of node tests that needed no CheckBox (the paper's ICA efficiency).
  double ica_efficiency() const { return node_tests == 0 ? 1.0 : 1.0 - double(checkbox_calls) / double(node_tests); }
};

struct AccessMap {
  SphereGrid sphere;
  std::vector<std::uint8_t> cells;  // row-major, 1 = collision
  AmStats stats;

  bool collides(int i, int j) const { return cells[std::size_t(i) * std::size_t(sphere.cols) + std::size_t(j)] != 0; }
  long collisions() const;
  std::vector<std::string> rows() const;  // '0' / '1' per cell
};

// Throws std::invalid_argument when the pivot lies in the closed box of a solid voxel (inside
// the part) or the tool is malformed (b < a, r < 0, non-finite, no cylinder).
AccessMap compute_access_map(const Octree& octree, const Vec3& pivot, const Tool& tool, const SphereGrid& sphere,
                             const AmOptions& options = {});

}  // namespace mtcs::voxel
