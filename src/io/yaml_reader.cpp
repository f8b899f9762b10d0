#include "mtcs/io/yaml_reader.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string_view>
#include <vector>

namespace mtcs::io {

std::string indexed(const std::string& path, std::size_t i) {
  std::string s = path;
  s += '[';
  s += std::to_string(i);
  s += ']';
  return s;
}

namespace {

// Optimal string alignment distance (Levenshtein plus adjacent swaps): a typo's size.
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i)
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t change = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + change});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

// The allowed key a mistyped one most likely meant: the single nearest within a third of its
// length (at least one edit), or none.
std::string_view nearest_key(const std::string& key, std::initializer_list<std::string_view> allowed) {
  std::string_view best;
  std::size_t best_d = std::max<std::size_t>(1, key.size() / 3) + 1;
  bool tie = false;
  for (const auto& a : allowed) {
    const std::size_t d = edit_distance(key, a);
    if (d < best_d) best = a, best_d = d, tie = false;
    else if (d == best_d) tie = true;
  }
  return tie ? std::string_view() : best;
}

}  // namespace

namespace {

// " (line L, column C holds a tab: YAML indents with spaces only)" for the first tab in a line's
// leading whitespace up to `last_line` (1-based; the parser stops at or after the mistake), or "".
std::string tab_hint(const std::string& text, int last_line) {
  std::istringstream in(text);
  std::string line;
  for (int n = 1; n <= last_line && std::getline(in, line); ++n) {
    const std::size_t indent = line.find_first_not_of(" \t");
    const std::size_t tab = line.find('\t');
    if (tab != std::string::npos && (indent == std::string::npos || tab < indent))
      return " (line " + std::to_string(n) + ", column " + std::to_string(tab + 1) +
             " holds a tab: YAML indents with spaces only)";
  }
  return "";
}

}  // namespace

YAML::Node parse_yaml(const std::string& text, const std::string& origin) {
  try {
    return YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    throw io::InputError(origin, e.mark.line + 1, e.mark.column + 1, "", "YAML syntax: " + e.msg + tab_hint(text, e.mark.line + 1));
  }
}

YAML::Node YamlReader::load() const {
  std::ifstream in(file_, std::ios::binary);
  if (!in || std::filesystem::is_directory(file_)) throw io::InputError(file_, 0, 0, "", "cannot open file");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_yaml(text.str(), file_);
}

void YamlReader::fail(const YAML::Node& at, const std::string& path, const std::string& what) const {
  const YAML::Mark m = at.Mark();
  throw io::InputError(file_, m.line + 1, m.column + 1, path, what);
}

void YamlReader::expect_map(const YAML::Node& n, const std::string& path,
                            std::initializer_list<std::string_view> allowed) const {
  if (!n.IsMap()) fail(n, path, "expected a mapping (key: value)");
  std::set<std::string> seen;
  for (auto it = n.begin(); it != n.end(); ++it) {
    const std::string key = it->first.Scalar();
    const std::string child = path.empty() ? key : path + "." + key;
    bool known = false;
    for (const auto& a : allowed) known = known || a == key;
    if (!known) {
      std::ostringstream list;
      for (const auto& a : allowed) list << (list.tellp() > 0 ? ", " : "") << a;
      const std::string_view near = nearest_key(key, allowed);
      fail(it->first, child,
           near.empty() ? "unknown key; expected one of: " + list.str()
                        : "unknown key; did you mean '" + std::string(near) + "'? (expected one of: " + list.str() + ")");
    }
    if (!seen.insert(key).second) fail(it->first, child, "duplicate key");
  }
}

void YamlReader::expect_sequence(const YAML::Node& n, const std::string& path) const {
  if (!n.IsSequence()) fail(n, path, "expected a list");
}

double YamlReader::number(const YAML::Node& n, const std::string& path, double lo, double hi) const {
  if (!n.IsScalar()) fail(n, path, "expected a number");
  const std::string& s = n.Scalar();
  double v = 0;
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec == std::errc::result_out_of_range && ptr == s.data() + s.size())
    fail(n, path, "'" + s + "' is beyond the range of a double");
  if (s.empty() || ec != std::errc() || ptr != s.data() + s.size() || !std::isfinite(v))
    fail(n, path, "expected a number, got '" + s + "'");
  if (v < lo || v > hi) {
    std::ostringstream msg;
    msg << "value " << v << " is out of range [" << lo << ", " << hi << "]";
    fail(n, path, msg.str());
  }
  return v;
}

int YamlReader::integer(const YAML::Node& n, const std::string& path, int lo, int hi) const {
  if (!n.IsScalar()) fail(n, path, "expected a whole number");
  const std::string& s = n.Scalar();
  int v = 0;
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (s.empty() || ec != std::errc() || ptr != s.data() + s.size())
    fail(n, path, "expected a whole number, got '" + s + "'");
  if (v < lo || v > hi)
    fail(n, path, "value " + std::to_string(v) + " is out of range [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return v;
}

bool YamlReader::boolean(const YAML::Node& n, const std::string& path) const {
  if (n.IsScalar()) {
    const std::string& s = n.Scalar();
    if (s == "true") return true;
    if (s == "false") return false;
  }
  fail(n, path, "expected true or false");
}

std::string YamlReader::text(const YAML::Node& n, const std::string& path) const {
  if (!n.IsScalar()) fail(n, path, "expected a string");
  return n.Scalar();
}

geometry::Vec3 YamlReader::vec3(const YAML::Node& n, const std::string& path) const {
  if (!n.IsSequence() || n.size() != 3) fail(n, path, "expected three numbers [x, y, z]");
  // Positions in mm within 1000 km: differences, squares and grid counts stay finite (1e308
  // was accepted and turned into infinities and NaN downstream).
  const double far = kMaxCoordinate;
  return {number(n[0], path + "[0]", -far, far), number(n[1], path + "[1]", -far, far),
          number(n[2], path + "[2]", -far, far)};
}

}  // namespace mtcs::io
