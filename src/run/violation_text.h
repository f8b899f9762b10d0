#pragma once
// The run store's words for a layout's violations: "kind element element distance/margin; ...",
// numbers as printf's %.6g. Built for every child an optimiser scores, so without printf: its
// format parsing and locale cost more than the rest of the text.

#include <charconv>
#include <string>

namespace mtcs::run {

// Appends x as printf("%.6g", x) would (std::to_chars with a precision is specified as printf's
// conversion in the "C" locale: inf, nan and exponents alike).
inline void append_general6(std::string& out, double x) {
  char text[32];  // "-2.22507e-308": 13 characters at most
  out.append(text, std::to_chars(text, text + sizeof text, x, std::chars_format::general, 6).ptr);
}

}  // namespace mtcs::run
