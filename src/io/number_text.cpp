#include "mtcs/io/number_text.h"

#include <charconv>
#include <cmath>

namespace mtcs::io {

double round_to(double value, double step) {
  if (!(step > 0) || !std::isfinite(value)) return value;
  const double steps = std::round(value / step);
  const double per_unit = std::round(1 / step);
  // 0.01 is not a double: 3512 / 100 is the double nearest 35.12, 3512 * 0.01 may not be.
  if (per_unit >= 1 && std::abs(per_unit * step - 1) < 1e-12) return steps / per_unit;
  return steps * step;
}

std::string shortest(double value) {
  if (value == 0) return "0";  // not "-0"
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, value);
  return std::string(buf, r.ptr);
}

}  // namespace mtcs::io
