#pragma once
// Splitting a CSV line into trimmed fields with their columns, for the readers' error messages.

#include <string_view>
#include <vector>

namespace mtcs::io::detail {

struct Field {
  std::string_view text;
  int column;  // 1-based character column
};

inline std::vector<Field> split_csv_line(std::string_view line) {
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

}  // namespace mtcs::io::detail
