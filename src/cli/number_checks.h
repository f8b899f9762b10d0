#pragma once
// CLI11 checks for numeric options that say what they accept in words ("must be a whole number
// from 1 to 2000000000, got 0"), instead of CLI11's ranges up to the largest double printed in
// full, or a negative seed wrapped round to 2^64 - 1.

#include <CLI/CLI.hpp>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace mtcs::cli {

// Options that count (seeds, budgets): a whole number in [lo, hi].
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

// A finite number above 0 (lengths, bounds).
inline CLI::Validator positive_number() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        double v = 0;
        const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
        if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(v) || !(v > 0))
          return "must be a number above 0, got " + text;
        return {};
      },
      "> 0");
}

// `n` finite numbers separated by commas ("x,y,z"), in `into`; each that is not a number is
// refused as "OPTION: 'x' is not a finite number (expected x,y,z)".
inline CLI::Option* add_numbers(CLI::App* app, const std::string& name, std::vector<double>& into, int n,
                                const std::string& form, const std::string& help) {
  const CLI::Validator finite(
      [form](std::string& text) -> std::string {
        double v = 0;
        const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
        if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(v))
          return "'" + text + "' is not a finite number (expected " + form + ")";
        return {};
      },
      form);
  return app->add_option(name, into, help)->delimiter(',')->expected(n)->type_name(form)->check(finite);
}

// The numbers as the user would write them back: shortest exact form, comma-separated.
inline std::string join_numbers(const std::vector<double>& v) {
  std::string out;
  for (const double x : v) {
    char buf[32];
    const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, x);
    out += (out.empty() ? "" : ",") + std::string(buf, end);
  }
  return out;
}

}  // namespace mtcs::cli
