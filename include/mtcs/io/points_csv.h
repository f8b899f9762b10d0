#pragma once
// A CSV of points, one a row, with columns x, y, z (mm) found by header name; other columns are
// ignored (the reference's T, say).

#include <string>
#include <vector>

#include "mtcs/geometry/primitives.h"

namespace mtcs::io {

// Throws InputError (file, line, column, field) on the first malformed row. `lines`, when given,
// receives each point's line in the file (for errors about a point the reader cannot judge).
std::vector<geometry::Vec3> read_points_csv(const std::string& path, std::vector<int>* lines = nullptr);

}  // namespace mtcs::io
