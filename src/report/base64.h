#pragma once
// Numbers for the page as base64 of their little-endian bytes: a mesh of 50 000 vertices is
// 0.8 MB of float32 text instead of 3 MB of decimals, and the page reads it with one
// Float32Array (report.js, decode()).

#include <cstdint>
#include <string>
#include <vector>

namespace mtcs::report {

std::string base64(const void* data, std::size_t bytes);
std::string base64_floats(const std::vector<float>& values);
std::string base64_indices(const std::vector<std::uint32_t>& values);

}  // namespace mtcs::report
