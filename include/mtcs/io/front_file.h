#pragma once
// Fronts in the format of shared/cases/hv_fronts: one point per line (whitespace-separated),
// "# ref r1 r2 ..." for the reference point, other '#' lines ignored.

#include <string>
#include <vector>

namespace mtcs::io {

struct FrontFile {
  std::vector<std::vector<double>> points;
  std::vector<double> ref;  // empty when the file has no "# ref" line
};

// Throws InputError (file, line, column, field) on a malformed number or a ragged row.
FrontFile read_front(const std::string& path);

}  // namespace mtcs::io
