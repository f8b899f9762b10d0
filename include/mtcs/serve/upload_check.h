#pragma once
// An uploaded component read back by the CLI's own readers before it is stored: a mesh must
// bound a solid (closed, oriented, no self-intersection), as `mtcs interfere` asks. Throws
// std::runtime_error with the reader's message; returns what the page shows of it.

#include <filesystem>

#include <nlohmann/json.hpp>

namespace mtcs::serve {

nlohmann::json check_component(const std::filesystem::path& staged);

}  // namespace mtcs::serve
