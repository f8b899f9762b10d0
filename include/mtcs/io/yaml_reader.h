#pragma once
// Typed access to a yaml-cpp tree that reports every problem as io::InputError at the node's
// line and column, with the field's path. yaml-cpp accepts duplicate keys silently; this
// reader does not.

#include <yaml-cpp/yaml.h>

#include <initializer_list>
#include <string>
#include <string_view>

#include "mtcs/geometry/primitives.h"
#include "mtcs/io/input_error.h"

namespace mtcs::io {

// The largest coordinate vec3 accepts (mm).
inline constexpr double kMaxCoordinate = 1e9;

// "path[i]".
std::string indexed(const std::string& path, std::size_t i);

// YAML `text` parsed, or its syntax error as an InputError at `origin`'s line and column; a tab
// in the indentation (yaml-cpp says only "illegal map value" or the like) is named.
YAML::Node parse_yaml(const std::string& text, const std::string& origin);

class YamlReader {
 public:
  explicit YamlReader(std::string file) : file_(std::move(file)) {}

  const std::string& file() const { return file_; }

  // Parses the reader's file; a missing file or a syntax error is an InputError.
  YAML::Node load() const;

  [[noreturn]] void fail(const YAML::Node& at, const std::string& path, const std::string& what) const;

  // A map whose keys are all in `allowed`, each at most once.
  void expect_map(const YAML::Node& n, const std::string& path,
                  std::initializer_list<std::string_view> allowed) const;
  void expect_sequence(const YAML::Node& n, const std::string& path) const;

  double number(const YAML::Node& n, const std::string& path, double lo, double hi) const;
  int integer(const YAML::Node& n, const std::string& path, int lo, int hi) const;
  bool boolean(const YAML::Node& n, const std::string& path) const;
  std::string text(const YAML::Node& n, const std::string& path) const;
  geometry::Vec3 vec3(const YAML::Node& n, const std::string& path) const;

 private:
  std::string file_;
};

}  // namespace mtcs::io
