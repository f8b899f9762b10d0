#pragma once
// The review app's files (src/serve/assets), compiled in by cmake/EmbedAssets.cmake: the server
// reads nothing from disk to serve its pages.

#include <string>
#include <string_view>

namespace mtcs::serve::assets {

std::string text(std::string_view name);  // "app.html", "app.js", "app.css", "favicon.svg"

}  // namespace mtcs::serve::assets
