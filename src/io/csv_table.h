#pragma once
// A CSV file addressed by header names, read row by row, whose every error names the file, the
// line, the column and the field: the common part of the pair and cylinder readers.

#include <fstream>
#include <string>
#include <string_view>
#include <vector>

namespace mtcs::io::detail {

struct Field {
  std::string_view text;  // trimmed; points into the current line
  int column;             // 1-based character column
};

std::vector<Field> split_csv_line(std::string_view line);

class CsvTable {
 public:
  // Opens the file and reads its header line; throws InputError when it cannot.
  explicit CsvTable(std::string path);

  // Index of the column named `name` (its last occurrence): required ones throw InputError
  // naming the field when missing, optional ones give -1.
  int required(std::string_view name) const;
  int optional(std::string_view name) const;

  // Advances to the next data row, over blank lines and # comments; false at the end.
  bool next();
  int line() const { return lineno_; }

  // The current row's field in column j, or InputError when the row is too short.
  const Field& field(int j, std::string_view name) const;
  // The field as a finite double, or InputError at its column.
  double number(int j, std::string_view name) const;
  [[noreturn]] void fail(int j, std::string_view name, const std::string& message) const;

 private:
  std::string path_;
  std::ifstream in_;
  std::string header_line_, line_;
  std::vector<Field> header_, fields_;
  int lineno_ = 1;
};

}  // namespace mtcs::io::detail
