#include "mtcs/io/pairs_csv.h"

#include <array>
#include <string_view>

#include "csv_table.h"

namespace mtcs::io {
namespace {

constexpr std::array<std::string_view, 15> kPairColumns{
    "id", "p0x", "p0y", "p0z", "p1x", "p1y", "p1z", "r0",
    "q0x", "q0y", "q0z", "q1x", "q1y", "q1z", "r1"};

}  // namespace

std::vector<CylinderPair> read_pairs_csv(const std::string& path) {
  detail::CsvTable table(path);
  std::array<int, kPairColumns.size()> col{};
  for (std::size_t k = 0; k < kPairColumns.size(); ++k) col[k] = table.required(kPairColumns[k]);
  const int lo_col = table.optional("dist_lo"), hi_col = table.optional("dist_hi"), cat_col = table.optional("category");

  std::vector<CylinderPair> pairs;
  while (table.next()) {
    CylinderPair p;
    p.line = table.line();
    p.id = std::string(table.field(col[0], "id").text);
    double v[14];
    for (int k = 1; k < 15; ++k) v[k - 1] = table.number(col[std::size_t(k)], kPairColumns[std::size_t(k)]);
    p.a = {{v[0], v[1], v[2]}, {v[3], v[4], v[5]}, v[6]};
    p.b = {{v[7], v[8], v[9]}, {v[10], v[11], v[12]}, v[13]};
    if (p.a.radius < 0) table.fail(col[7], "r0", "radius must be >= 0");
    if (p.b.radius < 0) table.fail(col[14], "r1", "radius must be >= 0");
    if (lo_col >= 0 && !table.field(lo_col, "dist_lo").text.empty()) p.dist_lo = table.number(lo_col, "dist_lo");
    if (hi_col >= 0 && !table.field(hi_col, "dist_hi").text.empty()) p.dist_hi = table.number(hi_col, "dist_hi");
    if (cat_col >= 0) p.category = std::string(table.field(cat_col, "category").text);
    pairs.push_back(std::move(p));
  }
  return pairs;
}

}  // namespace mtcs::io
