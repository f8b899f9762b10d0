#pragma once
// Numbers in the files a shop reads: rounded to a stated step (0.01 mm) and written in the
// fewest digits that read back as the same double ("35.12", not "35.119999999999997").

#include <string>

namespace mtcs::io {

// The nearest multiple of `step` (> 0): for steps like 0.01, computed as an integer over 100 so
// that the result is the double nearest to the decimal.
double round_to(double value, double step);

// The shortest text that reads back as exactly `value`.
std::string shortest(double value);

}  // namespace mtcs::io
