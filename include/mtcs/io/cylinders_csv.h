#pragma once
// A CSV of solid cylinders (bores), one a row: id,p0x,p0y,p0z,p1x,p1y,p1z,r. Columns are found
// by header name; the certified cases' dist_lo, dist_hi, category are read when present, other
// extra columns are ignored. The bores.csv of mtcs optimize reads as such a file too: `name` for
// id and `diameter` (halved) for r when those columns are absent.

#include <optional>
#include <string>
#include <vector>

#include "mtcs/geometry/primitives.h"

namespace mtcs::io {

struct NamedCylinder {
  std::string id;
  geometry::Cylinder cylinder;
  std::optional<double> dist_lo, dist_hi;  // certified interval, when the file has it
  std::string category;
  int line = 0;  // 1-based line in the file
};

// Throws InputError (file, line, column, field) on the first malformed row.
std::vector<NamedCylinder> read_cylinders_csv(const std::string& path);

}  // namespace mtcs::io
