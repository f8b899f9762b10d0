#include "mtcs/io/cylinders_csv.h"

#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <string_view>

#include "csv_fields.h"
#include "mtcs/io/input_error.h"

namespace mtcs::io {
namespace {

constexpr std::array<std::string_view, 8> kRequired{"id", "p0x", "p0y", "p0z", "p1x", "p1y", "p1z", "r"};

}  // namespace

std::vector<NamedCylinder> read_cylinders_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, 0, "", "cannot open file");
  std::string line;
  if (!std::getline(in, line)) throw InputError(path, 1, 1, "", "empty file: expected a header line");
  int lineno = 1;
  if (!line.empty() && line.back() == '\r') line.pop_back();
  const auto header = detail::split_csv_line(line);
  std::array<int, kRequired.size()> col{};
  for (std::size_t k = 0; k < kRequired.size(); ++k) {
    col[k] = -1;
    for (std::size_t j = 0; j < header.size(); ++j)
      if (header[j].text == kRequired[k]) col[k] = int(j);
    if (col[k] < 0) throw InputError(path, 1, 1, std::string(kRequired[k]), "required column missing from the header");
  }
  int lo_col = -1, hi_col = -1, cat_col = -1;
  for (std::size_t j = 0; j < header.size(); ++j) {
    if (header[j].text == "dist_lo") lo_col = int(j);
    if (header[j].text == "dist_hi") hi_col = int(j);
    if (header[j].text == "category") cat_col = int(j);
  }

  std::vector<NamedCylinder> cylinders;
  while (std::getline(in, line)) {
    ++lineno;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line.front() == '#') continue;
    const auto fields = detail::split_csv_line(line);
    auto field_at = [&](int j, std::string_view name) -> const detail::Field& {
      if (j >= int(fields.size()))
        throw InputError(path, lineno, int(line.size()) + 1, std::string(name),
                         "row has " + std::to_string(fields.size()) + " fields, header has " +
                             std::to_string(header.size()));
      return fields[j];
    };
    auto number = [&](int j, std::string_view name) {
      const detail::Field& f = field_at(j, name);
      double v = 0;
      const auto [ptr, ec] = std::from_chars(f.text.data(), f.text.data() + f.text.size(), v);
      if (f.text.empty() || ec != std::errc() || ptr != f.text.data() + f.text.size())
        throw InputError(path, lineno, f.column, std::string(name), "expected a number, got '" + std::string(f.text) + "'");
      if (!std::isfinite(v)) throw InputError(path, lineno, f.column, std::string(name), "value is not finite");
      return v;
    };
    NamedCylinder c;
    c.line = lineno;
    c.id = std::string(field_at(col[0], "id").text);
    std::array<double, 7> v;
    for (std::size_t k = 1; k < kRequired.size(); ++k) v[k - 1] = number(col[k], kRequired[k]);
    c.cylinder = {{v[0], v[1], v[2]}, {v[3], v[4], v[5]}, v[6]};
    if (c.cylinder.radius < 0) throw InputError(path, lineno, field_at(col[7], "r").column, "r", "radius must be >= 0");
    if (lo_col >= 0 && !field_at(lo_col, "dist_lo").text.empty()) c.dist_lo = number(lo_col, "dist_lo");
    if (hi_col >= 0 && !field_at(hi_col, "dist_hi").text.empty()) c.dist_hi = number(hi_col, "dist_hi");
    if (cat_col >= 0) c.category = std::string(field_at(cat_col, "category").text);
    cylinders.push_back(std::move(c));
  }
  return cylinders;
}

}  // namespace mtcs::io
