#include "csv_table.h"

#include <charconv>
#include <cmath>

#include "mtcs/io/input_error.h"

namespace mtcs::io::detail {
namespace {

void drop_carriage_return(std::string& line) {
  if (!line.empty() && line.back() == '\r') line.pop_back();
}

}  // namespace

std::vector<Field> split_csv_line(std::string_view line) {
  std::vector<Field> out;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = line.find(',', start);
    const std::size_t end = comma == std::string_view::npos ? line.size() : comma;
    std::string_view f = line.substr(start, end - start);
    while (!f.empty() && (f.front() == ' ' || f.front() == '\t')) f.remove_prefix(1);
    while (!f.empty() && (f.back() == ' ' || f.back() == '\t')) f.remove_suffix(1);
    out.push_back({f, int(start) + 1});
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return out;
}

CsvTable::CsvTable(std::string path) : path_(std::move(path)), in_(path_) {
  if (!in_) throw InputError(path_, 0, 0, "", "cannot open file");
  if (!std::getline(in_, header_line_)) throw InputError(path_, 1, 1, "", "empty file: expected a header line");
  drop_carriage_return(header_line_);
  header_ = split_csv_line(header_line_);
}

int CsvTable::optional(std::string_view name) const {
  int col = -1;
  for (std::size_t j = 0; j < header_.size(); ++j)
    if (header_[j].text == name) col = int(j);
  return col;
}

int CsvTable::required(std::string_view name) const {
  const int col = optional(name);
  if (col < 0) throw InputError(path_, 1, 1, std::string(name), "required column missing from the header");
  return col;
}

bool CsvTable::next() {
  while (std::getline(in_, line_)) {
    ++lineno_;
    drop_carriage_return(line_);
    if (line_.empty() || line_.front() == '#') continue;
    fields_ = split_csv_line(line_);
    return true;
  }
  return false;
}

const Field& CsvTable::field(int j, std::string_view name) const {
  if (j >= int(fields_.size()))
    throw InputError(path_, lineno_, int(line_.size()) + 1, std::string(name),
                     "row has " + std::to_string(fields_.size()) + " fields, header has " +
                         std::to_string(header_.size()));
  return fields_[std::size_t(j)];
}

double CsvTable::number(int j, std::string_view name) const {
  const Field& f = field(j, name);
  double v = 0;
  const auto [ptr, ec] = std::from_chars(f.text.data(), f.text.data() + f.text.size(), v);
  if (ec == std::errc::result_out_of_range && ptr == f.text.data() + f.text.size())
    throw InputError(path_, lineno_, f.column, std::string(name), "'" + std::string(f.text) + "' is beyond the range of a double");
  if (f.text.empty() || ec != std::errc() || ptr != f.text.data() + f.text.size())
    throw InputError(path_, lineno_, f.column, std::string(name), "expected a number, got '" + std::string(f.text) + "'");
  if (!std::isfinite(v)) throw InputError(path_, lineno_, f.column, std::string(name), "value is not finite");
  return v;
}

void CsvTable::fail(int j, std::string_view name, const std::string& message) const {
  throw InputError(path_, lineno_, field(j, name).column, std::string(name), message);
}

}  // namespace mtcs::io::detail
