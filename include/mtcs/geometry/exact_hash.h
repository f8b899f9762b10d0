// A hash of doubles by their exact bits, for caches keyed by exact geometry: equal keys are
// bit-identical inputs, so a hit returns what a fresh computation would.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace mtcs::geometry {

inline std::size_t exact_bits_hash(const double* values, std::size_t count, std::uint64_t seed = 0) {
  std::uint64_t h = 0x9e3779b97f4a7c15ull ^ seed;
  for (std::size_t i = 0; i < count; ++i) {
    std::uint64_t bits;
    std::memcpy(&bits, &values[i], sizeof bits);
    h = (h ^ bits) * 0xff51afd7ed558ccdull;
    h ^= h >> 32;
  }
  return std::size_t(h);
}

}  // namespace mtcs::geometry
