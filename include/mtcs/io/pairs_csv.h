#pragma once
// The cylinder-pair CSV of shared/cases (DESIGN.md, "Contracts"):
// id,p0x,p0y,p0z,p1x,p1y,p1z,r0,q0x,q0y,q0z,q1x,q1y,q1z,r1[,dist_lo,dist_hi,category]
// Columns are found by header name; extra columns are ignored.

#include <optional>
#include <string>
#include <vector>

#include "mtcs/geometry/primitives.h"

namespace mtcs::io {

struct CylinderPair {
  std::string id;
  geometry::Cylinder a;
  geometry::Cylinder b;
  std::optional<double> dist_lo, dist_hi;  // certified interval, when the file has it
  std::string category;
  int line = 0;  // 1-based line in the file
};

// Throws InputError (file, line, column, field) on the first malformed row.
std::vector<CylinderPair> read_pairs_csv(const std::string& path);

}  // namespace mtcs::io
