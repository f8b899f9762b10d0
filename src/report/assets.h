#pragma once
// The files of src/report/assets, compiled in by cmake/EmbedAssets.cmake: the page the report
// writes needs nothing beside the binary.

#include <string>
#include <string_view>

namespace mtcs::report::assets {

// The file's text by its path under src/report/assets ("report.js", "three/LICENSE", ...).
std::string text(std::string_view name);

}  // namespace mtcs::report::assets
