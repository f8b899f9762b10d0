#include "mesh_file_check.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <vector>

#include "mtcs/mesh/mesh_io.h"

namespace mtcs::mesh {
namespace {

std::string lowercase_extension(const std::string& path) {
  std::string e = std::filesystem::path(path).extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return e;
}

// The text with line numbers of stream positions, counted forward as the reader moves on.
class Lines {
 public:
  explicit Lines(const std::string& text) : text_(text) {}
  int at(std::streamoff pos) {
    const auto end = std::size_t(std::clamp<std::streamoff>(pos, 0, std::streamoff(text_.size())));
    for (; counted_ < end; ++counted_) line_ += text_[counted_] == '\n';
    return line_;
  }

 private:
  const std::string& text_;
  std::size_t counted_ = 0;
  int line_ = 1;
};

// CGAL's skip_comment_OFF: whitespace and '#' lines.
void skip_comment(std::istream& in) {
  char c = 0;
  while (in >> c && c == '#')
    while (in.get(c) && c != '\n') {
    }
  if (in) in.putback(c);
}

[[noreturn]] void fail(const std::string& path, int line, const std::string& what) {
  throw MeshError(path + ":" + std::to_string(line) + ": " + what);
}

// The coordinates of a vertex line, the three words from word `first` on: each a finite number
// of at most kMaxMeshCoordinate, refused at its line and column ("nan", "inf", "1e400", "1e308").
// Words that are no numbers are left to CGAL's reader, which refuses the file.
void check_coordinates(const std::string& path, int lineno, const std::string& line, std::size_t first, long long vertex) {
  std::size_t at = 0;
  for (std::size_t word = 0; word < first + 3; ++word) {
    at = line.find_first_not_of(" \t\r", at);
    if (at == std::string::npos) return;
    const std::size_t end = std::min(line.find_first_of(" \t\r", at), line.size());
    if (word >= first) {
      const std::string token = line.substr(at, end - at);
      char* stop = nullptr;
      const double v = std::strtod(token.c_str(), &stop);
      if (stop != token.c_str() + token.size()) return;
      if (!std::isfinite(v) || std::abs(v) > kMaxMeshCoordinate)
        throw MeshError(path + ":" + std::to_string(lineno) + ":" + std::to_string(at + 1) + ": vertex " +
                        std::to_string(vertex) + ": coordinate " + "xyz"[word - first] + " is '" + token.substr(0, 40) +
                        "', not a finite number of at most 1e9 in size");
    }
    at = end;
  }
}

// The vertex lines of an OBJ ("v x y z") or an ASCII STL ("vertex x y z").
void check_vertex_lines(const std::string& path, std::istream& in, const std::string& keyword) {
  std::string line;
  long long vertex = 0;
  for (int lineno = 1; std::getline(in, line); ++lineno) {
    const std::size_t at = line.find_first_not_of(" \t");
    if (at == std::string::npos || line.compare(at, keyword.size(), keyword) != 0) continue;
    const std::size_t after = at + keyword.size();
    if (after < line.size() && line[after] != ' ' && line[after] != '\t') continue;  // "vn", "vt", "vertices"
    check_coordinates(path, lineno, line, 1, vertex++);
  }
}

// Binary STL: 80 bytes of header, a triangle count, 50 bytes a triangle. A count that the file
// does not hold (10 million promised in 200 bytes) is named; CGAL only said it cannot read it.
void check_stl(const std::string& path, std::istream& in) {
  char head[84] = {};
  in.read(head, sizeof head);
  const std::size_t got = std::size_t(in.gcount());
  const bool ascii = got > 5 && std::string(head, 5) == "solid" && std::isspace(static_cast<unsigned char>(head[5]));
  in.clear();
  in.seekg(0);
  if (ascii) return check_vertex_lines(path, in, "vertex");
  const std::uintmax_t size = std::filesystem::file_size(path);
  if (size < 84) throw MeshError(path + ": " + std::to_string(size) + " bytes, too short for a binary STL (84 bytes of header)");
  std::uint32_t count = 0;
  for (int k = 3; k >= 0; --k) count = (count << 8) | static_cast<unsigned char>(head[80 + k]);
  if (count > kMaxMeshTriangles)
    throw MeshError(path + ": the binary STL header promises " + std::to_string(count) + " triangles, more than the " +
                    std::to_string(kMaxMeshTriangles) + " a mesh may have");
  const std::uint64_t expected = 84 + 50 * std::uint64_t(count);
  if (size != expected)
    throw MeshError(path + ": the binary STL header promises " + std::to_string(count) + " triangles (" +
                    std::to_string(expected) + " bytes), the file has " + std::to_string(size) + " bytes");
  // CGAL merges equal corners through an ordered map: a NaN compares equal to any point there
  // and silently became another vertex. Corners after the normal, little-endian floats; read a
  // block at a time (a mesh of 10 million triangles is 500 MB).
  static_assert(sizeof(float) == 4);
  in.seekg(84);
  std::vector<char> block(50 * 4096);
  for (std::uint32_t first = 0; first < count; first += 4096) {
    const std::uint32_t n = std::min<std::uint32_t>(4096, count - first);
    if (!in.read(block.data(), std::streamsize(50 * std::size_t(n)))) throw MeshError(path + ": cannot read its triangles");
    for (std::uint32_t t = 0; t < n; ++t)
      for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 3; ++k) {
          float v = 0;
          std::memcpy(&v, block.data() + 50 * std::size_t(t) + 12 * std::size_t(c + 1) + 4 * std::size_t(k), 4);
          if (!std::isfinite(v) || std::abs(v) > kMaxMeshCoordinate) {
            std::ostringstream value;
            value << v;
            throw MeshError(path + ": triangle " + std::to_string(first + t) + ", corner " + std::to_string(c) +
                            ": coordinate " + "xyz"[k] + " is " + value.str() + ", not a finite number of at most 1e9 in size");
          }
        }
  }
}

// ASCII OFF as CGAL's File_scanner_OFF reads it (a vertex or a face a line after the counts):
// CGAL casts a face's size and indices from double to size_t, undefined for negative or huge
// values; binary OFF and the variants (COFF, NOFF, STOFF, 4OFF, nOFF) are refused.
void check_off(const std::string& path, const std::string& text) {
  std::istringstream in(text);
  Lines lines(text);
  skip_comment(in);
  std::string keyword;
  const std::streamoff keyword_at = in.tellg();
  if (!(in >> keyword)) return;
  // Plain OFF only. CGAL's variants with colours, normals and texture ([ST][C][N][4][n]OFF)
  // overflowed a heap buffer on a short colour line (COFF), and CGAL took "OFF]" and then read
  // garbage counts.
  static const std::regex off_keyword("(ST)?C?N?4?n?OFF");
  if (!std::regex_match(keyword, off_keyword))
    fail(path, lines.at(keyword_at), "not an OFF file: it starts with '" + keyword.substr(0, 40) + "', not OFF");
  if (keyword != "OFF")
    fail(path, lines.at(keyword_at), "the OFF variant " + keyword + " is not supported: plain OFF only");
  std::vector<long long> counts;
  while (counts.size() < 3) {  // read as CGAL does: numbers from the stream, not words
    skip_comment(in);
    const std::streamoff at = in.tellg();
    if (at >= 0 && text.compare(std::size_t(at), 6, "BINARY") == 0)
      fail(path, lines.at(at), "binary OFF is not supported: use ASCII OFF, STL, OBJ or PLY");
    long long v = 0;
    if (!(in >> v)) return;  // CGAL refuses the header itself
    if (v < 0 || v > static_cast<long long>(kMaxMeshTriangles))
      fail(path, lines.at(at), "the header's count " + std::to_string(v) + " is out of range");
    counts.push_back(v);
  }
  const long long vertices = counts[0], faces = counts[1];
  // Every vertex and face takes a line of at least two bytes: CGAL read on at the end of the
  // file for as many as the header promised.
  if (double(vertices) + double(faces) > double(text.size()) / 2)
    fail(path, lines.at(keyword_at), "the header promises " + std::to_string(vertices) + " vertices and " +
                                         std::to_string(faces) + " faces, more than a file of " +
                                         std::to_string(text.size()) + " bytes holds");
  std::string line;
  for (long long v = 0; v < vertices; ++v) {
    skip_comment(in);
    const int lineno = lines.at(in.tellg());
    if (!std::getline(in, line)) return;
    check_coordinates(path, lineno, line.substr(0, line.find('#')), 0, v);
  }
  for (long long f = 0; f < faces; ++f) {
    skip_comment(in);
    const int lineno = lines.at(in.tellg());
    if (!std::getline(in, line)) return;
    line = line.substr(0, line.find('#'));
    std::istringstream numbers(line);
    std::vector<double> entries;
    for (double d = 0; numbers >> d;) entries.push_back(d);
    if (entries.empty()) return;
    const double size = entries[0];
    if (!(size >= 0 && size <= 1e6 && size == std::floor(size)))
      fail(path, lineno, "face " + std::to_string(f) + " has a corner count that is not a whole number up to 10^6");
    for (std::size_t k = 1; k <= std::size_t(size) && k < entries.size(); ++k)
      if (!(entries[k] >= 0 && entries[k] < double(vertices) && entries[k] == std::floor(entries[k])))
        fail(path, lineno, "face " + std::to_string(f) + " refers to vertex " + std::to_string(entries[k]) + ", not one of the " + std::to_string(vertices) + " vertices");
  }
}

// PLY header: CGAL's reader takes a negative element count as a huge one (reading on at the
// end of the file for hours), adds a property to the last element (undefined before the first)
// allocates a list as long as its count says (4.7 GB from one int32 count), and reads a
// vertex's x, y, z as float or double whatever their declared type (a null
// dereference for an integer type). A "halfedge" element's items are read as an unsigned int
// "source" and "target" whatever the header declares, so both must be there with that type.
void check_ply(const std::string& path, const std::string& text) {
  std::istringstream in(text);
  std::string line, element;
  long long items = 0;
  int element_line = 0;
  std::set<std::string> declared;                      // "element property"
  std::map<std::string, std::string> halfedge_types;  // property -> type, of the current halfedge element
  const auto check_halfedge = [&] {
    if (element != "halfedge" || items == 0) return;
    for (const char* property : {"source", "target"}) {
      const auto found = halfedge_types.find(property);
      const std::string type = found == halfedge_types.end() ? "" : found->second;
      if (type != "uint" && type != "uint32")
        fail(path, element_line,
             std::string("element halfedge needs the property ") + property + " as uint (uint32), " +
                 (type.empty() ? std::string("not declared") : "not " + type));
    }
  };
  for (int lineno = 1; std::getline(in, line); ++lineno) {
    std::istringstream words(line);
    std::string word, type, name;
    words >> word;
    if (word == "end_header") return check_halfedge();
    if (word == "element") {
      check_halfedge();
      halfedge_types.clear();
      element_line = lineno;
      std::string count;
      words >> element >> count;
      long long n = -1;
      std::istringstream number(count);
      if (!(number >> n) || !number.eof() || n < 0 || n > static_cast<long long>(kMaxMeshTriangles) ||
          n > static_cast<long long>(text.size()))  // every element takes a byte at least
        fail(path, lineno, "element " + element + " has the count '" + count + "', not a whole number from 0 to " +
                               std::to_string(kMaxMeshTriangles));
      items = n;
    }
    if (word != "property") continue;
    if (element.empty()) fail(path, lineno, "a property before any element");
    words >> type >> name;
    if (type == "list") {  // name is the count's type: CGAL allocates what the count says
      const bool small = name == "uchar" || name == "uint8" || name == "char" || name == "int8" || name == "ushort" ||
                         name == "uint16" || name == "short" || name == "int16";
      if (!small) fail(path, lineno, "a list counted in " + name + ": up to 16 bits (uchar, ushort) are supported");
      std::string index_type;
      words >> index_type >> name;
    }
    halfedge_types.emplace(name, type);
    // CGAL names a property by the word after its type(s); garbage after that is ignored, and a
    // type it does not know drops the property. Both that name and the line's last word are
    // checked, so a garbage type before "x" is refused too.
    std::string last = name;
    for (std::string more; words >> more;) last = more;
    std::vector<std::string> names{name};
    if (last != name) names.push_back(last);
    for (const std::string& n : names) {
      // CGAL finds a property by its name and reads it as the type it expects: a second x, or
      // an x of another type (an integer, a list), meets a reader of another type (a null
      // dereference).
      if (!declared.insert(element + " " + n).second)
        fail(path, lineno, "property " + n + " of element " + element + " is declared twice");
      // CGAL reads an element named "vertices" as the vertex element too (IO/PLY.h).
      const bool vertex_element = element == "vertex" || element == "vertices";
      const bool coordinate = vertex_element && (n == "x" || n == "y" || n == "z");
      if (coordinate && type == "list") fail(path, lineno, "vertex property " + n + " must be float or double, not a list");
      const bool real = type == "float" || type == "double" || type == "float32" || type == "float64";
      if (coordinate && !real) fail(path, lineno, "vertex property " + n + " must be float or double, not " + type);
    }
  }
}

}  // namespace

void check_mesh_file(const std::string& path) {
  const std::string ext = lowercase_extension(path);
  if (ext != ".off" && ext != ".ply" && ext != ".obj" && ext != ".stl") return;
  std::ifstream in(path, std::ios::binary);
  // STL and OBJ are checked as they stream by: no second copy of a large mesh in memory.
  if (ext == ".obj") return check_vertex_lines(path, in, "v");
  if (ext == ".stl") return check_stl(path, in);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  if (ext == ".off") check_off(path, text);
  else check_ply(path, text);
}

}  // namespace mtcs::mesh
