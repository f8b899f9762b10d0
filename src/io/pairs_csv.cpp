#include "mtcs/io/pairs_csv.h"

#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <string_view>

#include "csv_fields.h"
#include "mtcs/io/input_error.h"

namespace mtcs::io {
namespace {

constexpr std::array<std::string_view, 15> kRequired{
    "id", "p0x", "p0y", "p0z", "p1x", "p1y", "p1z", "r0",
    "q0x", "q0y", "q0z", "q1x", "q1y", "q1z", "r1"};

using detail::Field;

}  // namespace

std::vector<CylinderPair> read_pairs_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, 0, "", "cannot open file");
  std::string line;
  int lineno = 0;
  if (!std::getline(in, line)) throw InputError(path, 1, 1, "", "empty file: expected a header line");
  ++lineno;
  if (!line.empty() && line.back() == '\r') line.pop_back();
  const auto header = detail::split_csv_line(line);
  std::array<int, kRequired.size()> col{};
  int lo_col = -1, hi_col = -1, cat_col = -1;
  for (std::size_t k = 0; k < kRequired.size(); ++k) {
    col[k] = -1;
    for (std::size_t j = 0; j < header.size(); ++j)
      if (header[j].text == kRequired[k]) col[k] = int(j);
    if (col[k] < 0)
      throw InputError(path, 1, 1, std::string(kRequired[k]), "required column missing from the header");
  }
  for (std::size_t j = 0; j < header.size(); ++j) {
    if (header[j].text == "dist_lo") lo_col = int(j);
    if (header[j].text == "dist_hi") hi_col = int(j);
    if (header[j].text == "category") cat_col = int(j);
  }

  std::vector<CylinderPair> pairs;
  while (std::getline(in, line)) {
    ++lineno;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line.front() == '#') continue;
    const auto fields = detail::split_csv_line(line);
    auto field_at = [&](int j, std::string_view name) -> const Field& {
      if (j >= int(fields.size()))
        throw InputError(path, lineno, int(line.size()) + 1, std::string(name),
                         "row has " + std::to_string(fields.size()) + " fields, header has " +
                             std::to_string(header.size()));
      return fields[j];
    };
    auto number = [&](int j, std::string_view name) {
      const Field& f = field_at(j, name);
      double v = 0;
      const auto [ptr, ec] = std::from_chars(f.text.data(), f.text.data() + f.text.size(), v);
      if (f.text.empty() || ec != std::errc() || ptr != f.text.data() + f.text.size())
        throw InputError(path, lineno, f.column, std::string(name),
                         "expected a number, got '" + std::string(f.text) + "'");
      if (!std::isfinite(v))
        throw InputError(path, lineno, f.column, std::string(name), "value is not finite");
      return v;
    };
    CylinderPair p;
    p.line = lineno;
    p.id = std::string(field_at(col[0], "id").text);
    double v[14];
    for (int k = 1; k < 15; ++k) v[k - 1] = number(col[k], kRequired[k]);
    p.a = {{v[0], v[1], v[2]}, {v[3], v[4], v[5]}, v[6]};
    p.b = {{v[7], v[8], v[9]}, {v[10], v[11], v[12]}, v[13]};
    if (p.a.radius < 0) throw InputError(path, lineno, field_at(col[7], "r0").column, "r0", "radius must be >= 0");
    if (p.b.radius < 0) throw InputError(path, lineno, field_at(col[14], "r1").column, "r1", "radius must be >= 0");
    if (lo_col >= 0 && !field_at(lo_col, "dist_lo").text.empty()) p.dist_lo = number(lo_col, "dist_lo");
    if (hi_col >= 0 && !field_at(hi_col, "dist_hi").text.empty()) p.dist_hi = number(hi_col, "dist_hi");
    if (cat_col >= 0) p.category = std::string(field_at(cat_col, "category").text);
    pairs.push_back(std::move(p));
  }
  return pairs;
}

}  // namespace mtcs::io
