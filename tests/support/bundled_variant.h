#pragma once
// A bundled mold's spec with one line changed, written to this process's scratch folder with
// its mesh path made absolute: the variant a test needs (the wall-distance objectives of a mold
// that optimises temperatures, the void ignored where only the fields' names matter).

#include <fstream>
#include <functional>
#include <iterator>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "support/paths.h"
#include "support/scratch_file.h"

namespace mtcs_test {

// molds/<mold>.yaml with each `from` (which must be there) replaced by its `to`, in order.
inline std::string bundled_variant(const std::string& mold,
                                   const std::vector<std::pair<std::string, std::string>>& changes) {
  std::ifstream in(MTCS_SOURCE_DIR + "/molds/" + mold + ".yaml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::string key;
  for (const auto& [from, to] : changes) {
    if (text.find(from) == std::string::npos) throw std::runtime_error("bundled_variant: '" + from + "' not in " + mold);
    text.replace(text.find(from), from.size(), to);
    key += from + '\0' + to + '\0';
  }
  const std::string mesh = "mesh: meshes/";
  if (text.find(mesh) != std::string::npos) text.replace(text.find(mesh), mesh.size(), "mesh: " + MTCS_SOURCE_DIR + "/molds/meshes/");
  return write_scratch("bundled_variant", mold + "_" + std::to_string(std::hash<std::string>{}(key)) + ".yaml", text).string();
}

// molds/<mold>.yaml with `from` (which must be there) replaced by `to`.
inline std::string bundled_variant(const std::string& mold, const std::string& from, const std::string& to) {
  return bundled_variant(mold, {{from, to}});
}

// The mold with the wall-distance objectives (tier 0), or the bundled file if it has them.
inline std::string wall_distance_spec(const std::string& mold) {
  const std::string use = "use: [temperature_std, cycle_time, cost]";
  std::ifstream in(MTCS_SOURCE_DIR + "/molds/" + mold + ".yaml");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (text.find(use) == std::string::npos) return MTCS_SOURCE_DIR + "/molds/" + mold + ".yaml";
  return bundled_variant(mold, use, "use: [uniformity, worst_covered, cost]");
}

}  // namespace mtcs_test
