// Reader and writer of accessibility-map case files.

#include "mtcs/voxel/access_case.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <ostream>
#include <sstream>

#include "mtcs/io/input_error.h"

namespace mtcs::voxel {
namespace {

struct Token {
  std::string text;
  int column;  // 1-based
};

std::vector<Token> split(const std::string& line) {
  std::vector<Token> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    const std::size_t start = i;
    while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    if (i > start) out.push_back({line.substr(start, i - start), int(start) + 1});
  }
  return out;
}

class LineParser {
 public:
  LineParser(const std::string& file, int line, std::vector<Token> tokens)
      : file_(file), line_(line), tokens_(std::move(tokens)) {}

  [[noreturn]] void fail(std::size_t token, const std::string& field, const std::string& what) const {
    const int col = token < tokens_.size() ? tokens_[token].column : (tokens_.empty() ? 1 : tokens_.back().column);
    throw io::InputError(file_, line_, col, field, what);
  }
  void expect_count(std::size_t n, const std::string& field) const {
    if (tokens_.size() != n) fail(tokens_.size() < n ? tokens_.size() : n, field, "expected " + std::to_string(n - 1) + " value(s) after '" + tokens_[0].text + "'");
  }
  double number(std::size_t k, const std::string& field) const {
    if (k >= tokens_.size()) fail(k, field, "missing number");
    const std::string& t = tokens_[k].text;
    double v = 0;
    const auto [ptr, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec != std::errc() || ptr != t.data() + t.size() || !std::isfinite(v)) fail(k, field, "not a finite number: '" + t + "'");
    return v;
  }
  long integer(std::size_t k, const std::string& field, long min) const {
    if (k >= tokens_.size()) fail(k, field, "missing integer");
    const std::string& t = tokens_[k].text;
    long v = 0;
    const auto [ptr, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec != std::errc() || ptr != t.data() + t.size()) fail(k, field, "not an integer: '" + t + "'");
    if (v < min) fail(k, field, "must be >= " + std::to_string(min));
    return v;
  }
  Vec3 vec3(const std::string& field) const {
    expect_count(4, field);
    return {number(1, field), number(2, field), number(3, field)};
  }
  const std::vector<Token>& tokens() const { return tokens_; }

 private:
  const std::string& file_;
  int line_;
  std::vector<Token> tokens_;
};

}  // namespace

AccessCase read_access_case(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw io::InputError(path, 0, 0, "", "cannot open case file");
  AccessCase c;
  c.path = path;
  std::string line;
  while (std::getline(in, line)) c.lines.push_back(line);
  long rows = -1, cols = -1;
  bool have_grid = false, have_size = false, have_origin = false, have_pivot = false, have_mesh = false;
  for (std::size_t n = 0; n < c.lines.size(); ++n) {
    auto tokens = split(c.lines[n]);
    if (tokens.empty() || tokens[0].text[0] == '#') continue;
    const LineParser p(path, int(n) + 1, tokens);
    const std::string& key = tokens[0].text;
    if (key == "mesh") {
      p.expect_count(2, key);
      c.mesh = tokens[1].text;
      have_mesh = true;
    } else if (key == "scale") {
      p.expect_count(2, key);
      c.scale = p.number(1, key);
      if (!(c.scale > 0)) p.fail(1, key, "must be > 0");
    } else if (key == "centre") {
      c.centre = p.vec3(key);
    } else if (key == "translation") {
      p.vec3(key);  // informative; the centre form is the one used
    } else if (key == "grid") {
      p.expect_count(4, key);
      for (int a = 0; a < 3; ++a) c.grid.size[std::size_t(a)] = int(p.integer(std::size_t(a) + 1, key, 1));
      for (int a = 0; a < 3; ++a)
        if (c.grid.size[std::size_t(a)] > 512) p.fail(std::size_t(a) + 1, key, "at most 512 voxels across");
      have_grid = true;
    } else if (key == "voxel_size") {
      p.expect_count(2, key);
      c.grid.voxel_size = p.number(1, key);
      if (!(c.grid.voxel_size > 0)) p.fail(1, key, "must be > 0");
      have_size = true;
    } else if (key == "grid_origin") {
      c.grid.origin = p.vec3(key);
      have_origin = true;
    } else if (key == "solid_voxels" || key == "octree_nodes") {
      p.expect_count(2, key);
      (key == "solid_voxels" ? c.solid_voxels : c.octree_nodes) = p.integer(1, key, 0);
    } else if (key == "pivot") {
      c.pivot = p.vec3(key);
      c.pivot_line = int(n) + 1;
      have_pivot = true;
    } else if (key == "tool_cylinders") {
      p.expect_count(2, key);
      const long k = p.integer(1, key, 1);
      for (long m = 0; m < k; ++m) {
        ++n;
        if (n >= c.lines.size()) p.fail(1, key, "file ends before cylinder " + std::to_string(m + 1) + " of " + std::to_string(k));
        const LineParser q(path, int(n) + 1, split(c.lines[n]));
        const auto& t = q.tokens();
        if (t.size() != 7 || t[0].text != "cyl" || t[1].text != "a" || t[3].text != "b" || t[5].text != "r")
          q.fail(0, "cyl", "expected 'cyl a A b B r R'");
        ToolCylinder cyl{q.number(2, "cyl.a"), q.number(4, "cyl.b"), q.number(6, "cyl.r")};
        if (cyl.a < 0) q.fail(2, "cyl.a", "must be >= 0");
        if (cyl.b < cyl.a) q.fail(4, "cyl.b", "must be >= a");
        if (cyl.r < 0) q.fail(6, "cyl.r", "must be >= 0");
        c.tool.push_back(cyl);
      }
    } else if (key == "am_rows" || key == "am_cols") {
      p.expect_count(2, key);
      (key == "am_rows" ? rows : cols) = p.integer(1, key, 1);
      if ((key == "am_rows" ? rows : cols) > 4096) p.fail(1, key, "at most 4096");
    } else if (key == "collisions") {
      p.expect_count(2, key);
      c.collisions = p.integer(1, key, 0);
    } else if (key == "am") {
      p.expect_count(1, key);
      if (rows < 0 || cols < 0) p.fail(0, key, "am_rows and am_cols must come before am");
      for (long m = 0; m < rows; ++m) {
        ++n;
        if (n >= c.lines.size()) p.fail(0, key, "file ends after " + std::to_string(m) + " of " + std::to_string(rows) + " rows");
        const std::string& row = c.lines[n];
        if (long(row.size()) != cols) throw io::InputError(path, int(n) + 1, 1, "am", "row of " + std::to_string(row.size()) + " cells, expected " + std::to_string(cols));
        for (std::size_t ch = 0; ch < row.size(); ++ch)
          if (row[ch] != '0' && row[ch] != '1') throw io::InputError(path, int(n) + 1, int(ch) + 1, "am", "cell is not 0 or 1");
        c.am.push_back(row);
      }
    } else {
      p.fail(0, key, "unknown key '" + key + "'");
    }
  }
  const auto missing = [&](bool have, const std::string& field) {
    if (!have) throw io::InputError(path, int(c.lines.size()), 1, field, "missing");
  };
  missing(have_mesh, "mesh");
  missing(have_grid, "grid");
  missing(have_size, "voxel_size");
  missing(have_origin, "grid_origin");
  missing(have_pivot, "pivot");
  missing(!c.tool.empty(), "tool_cylinders");
  missing(rows > 0, "am_rows");
  missing(cols > 0, "am_cols");
  c.sphere.rows = int(rows);
  c.sphere.cols = int(cols);
  return c;
}

mesh::TriangleMesh scale_case_mesh(const mesh::TriangleMesh& raw, const AccessCase& c) {
  mesh::TriangleMesh m = raw;
  for (Vec3& v : m.vertices)
    for (int a = 0; a < 3; ++a) v[a] = c.scale * (v[a] - c.centre[a]);
  return m;
}

void write_access_case(std::ostream& out, const AccessCase& c, const std::vector<std::string>& map) {
  long ones = 0;
  for (const auto& row : map)
    for (char ch : row) ones += ch == '1';
  bool wrote_collisions = false, wrote_am = false;
  for (std::size_t n = 0; n < c.lines.size(); ++n) {
    const auto tokens = split(c.lines[n]);
    const std::string key = tokens.empty() ? "" : tokens[0].text;
    if (key == "collisions") {
      out << "collisions " << ones << '\n';
      wrote_collisions = true;
    } else if (key == "am") {
      if (!wrote_collisions) out << "collisions " << ones << '\n';
      wrote_collisions = true;
      out << "am\n";
      for (const auto& row : map) out << row << '\n';
      n += c.am.size();  // skip the old rows
      wrote_am = true;
    } else {
      out << c.lines[n] << '\n';
    }
  }
  if (!wrote_collisions) out << "collisions " << ones << '\n';
  if (!wrote_am) {
    out << "am\n";
    for (const auto& row : map) out << row << '\n';
  }
}

}  // namespace mtcs::voxel
