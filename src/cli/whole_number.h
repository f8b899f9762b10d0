#pragma once
// A CLI11 check for options that count (seeds, budgets): a whole number in [lo, hi], refused
// with the range written out ("must be a whole number from 1 to 2000000000, got 0") instead of
// CLI11's floating-point range or a negative number wrapped round to 2^64 - 1.

#include <CLI/CLI.hpp>

#include <charconv>
#include <cstdint>
#include <string>

namespace mtcs::cli {

inline CLI::Validator whole_number(std::int64_t lo, std::int64_t hi) {
  const std::string range = "a whole number from " + std::to_string(lo) + " to " + std::to_string(hi);
  return CLI::Validator(
      [lo, hi, range](std::string& text) -> std::string {
        std::int64_t v = 0;
        const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
        if (ec != std::errc() || end != text.data() + text.size() || v < lo || v > hi)
          return "must be " + range + ", got " + text;
        return {};
      },
      "in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
}

}  // namespace mtcs::cli
