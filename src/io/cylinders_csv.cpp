#include "mtcs/io/cylinders_csv.h"

#include <array>
#include <string_view>

#include "csv_table.h"

namespace mtcs::io {
namespace {

constexpr std::array<std::string_view, 8> kCylinderColumns{"id", "p0x", "p0y", "p0z", "p1x", "p1y", "p1z", "r"};

}  // namespace

std::vector<NamedCylinder> read_cylinders_csv(const std::string& path) {
  detail::CsvTable table(path);
  std::array<int, kCylinderColumns.size()> col{};
  // bores.csv of mtcs optimize names its cylinders and gives diameters: read as id and r.
  const int name_col = table.optional("name"), diameter_col = table.optional("diameter");
  const bool by_name = table.optional("id") < 0 && name_col >= 0;
  const bool by_diameter = table.optional("r") < 0 && diameter_col >= 0;
  for (std::size_t k = 0; k < kCylinderColumns.size(); ++k)
    col[k] = k == 0 && by_name ? name_col : k == 7 && by_diameter ? diameter_col : table.required(kCylinderColumns[k]);
  const int lo_col = table.optional("dist_lo"), hi_col = table.optional("dist_hi"), cat_col = table.optional("category");

  std::vector<NamedCylinder> cylinders;
  while (table.next()) {
    NamedCylinder c;
    c.line = table.line();
    c.id = std::string(table.field(col[0], by_name ? "name" : "id").text);
    std::array<double, 7> v;
    for (std::size_t k = 1; k < kCylinderColumns.size(); ++k)
      v[k - 1] = table.number(col[k], k == 7 && by_diameter ? "diameter" : kCylinderColumns[k]);
    c.cylinder = {{v[0], v[1], v[2]}, {v[3], v[4], v[5]}, by_diameter ? v[6] / 2 : v[6]};
    if (c.cylinder.radius < 0) table.fail(col[7], by_diameter ? "diameter" : "r", "must be >= 0");
    if (lo_col >= 0 && !table.field(lo_col, "dist_lo").text.empty()) c.dist_lo = table.number(lo_col, "dist_lo");
    if (hi_col >= 0 && !table.field(hi_col, "dist_hi").text.empty()) c.dist_hi = table.number(hi_col, "dist_hi");
    if (cat_col >= 0) c.category = std::string(table.field(cat_col, "category").text);
    cylinders.push_back(std::move(c));
  }
  return cylinders;
}

}  // namespace mtcs::io
