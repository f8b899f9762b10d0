#include "mtcs/io/points_csv.h"

#include "csv_table.h"

namespace mtcs::io {

std::vector<geometry::Vec3> read_points_csv(const std::string& path, std::vector<int>* lines) {
  detail::CsvTable table(path);
  const int x = table.required("x"), y = table.required("y"), z = table.required("z");
  std::vector<geometry::Vec3> points;
  while (table.next()) {
    points.emplace_back(table.number(x, "x"), table.number(y, "y"), table.number(z, "z"));
    if (lines) lines->push_back(table.line());
  }
  return points;
}

}  // namespace mtcs::io
