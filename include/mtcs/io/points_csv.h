#pragma once
// A CSV of points, one a row, with columns x, y, z (mm) found by header name; other columns are
// ignored (the reference's T, say).

#include <string>
#include <vector>

#include "mtcs/geometry/primitives.h"

namespace mtcs::io {

// Throws InputError (file, line, column, field) on the first malformed row.
std::vector<geometry::Vec3> read_points_csv(const std::string& path);

}  // namespace mtcs::io
