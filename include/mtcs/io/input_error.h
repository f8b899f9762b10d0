#pragma once
// The one error type for bad user input: it names the file, the line and column, and the field,
// and the command turns it into one message and exit code 2.

#include <stdexcept>
#include <string>

namespace mtcs::io {

class InputError : public std::runtime_error {
 public:
  InputError(std::string file, int line, int column, std::string field, const std::string& what)
      : std::runtime_error(file + ":" + std::to_string(line) + ":" + std::to_string(column) +
                           ": " + (field.empty() ? "" : "field '" + field + "': ") + what),
        file_(std::move(file)), line_(line), column_(column), field_(std::move(field)) {}

  const std::string& file() const { return file_; }
  int line() const { return line_; }
  int column() const { return column_; }
  const std::string& field() const { return field_; }

 private:
  std::string file_;
  int line_;
  int column_;
  std::string field_;
};

}  // namespace mtcs::io
