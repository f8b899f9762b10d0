#include "base64.h"

#include <bit>

namespace mtcs::report {

static_assert(std::endian::native == std::endian::little, "the page reads little-endian typed arrays");

std::string base64(const void* data, std::size_t bytes) {
  static constexpr char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  const auto* in = static_cast<const unsigned char*>(data);
  std::string out;
  out.reserve((bytes + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes; i += 3) {
    const std::uint32_t n = std::uint32_t(in[i]) << 16 | (i + 1 < bytes ? std::uint32_t(in[i + 1]) << 8 : 0u) |
                            (i + 2 < bytes ? std::uint32_t(in[i + 2]) : 0u);
    out += digits[n >> 18 & 63];
    out += digits[n >> 12 & 63];
    out += i + 1 < bytes ? digits[n >> 6 & 63] : '=';
    out += i + 2 < bytes ? digits[n & 63] : '=';
  }
  return out;
}

std::string base64_floats(const std::vector<float>& values) { return base64(values.data(), values.size() * sizeof(float)); }

std::string base64_indices(const std::vector<std::uint32_t>& values) {
  return base64(values.data(), values.size() * sizeof(std::uint32_t));
}

}  // namespace mtcs::report
