#include "mesh_file_check.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
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
    if (!std::getline(in, line)) return;
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
// dereference for an integer type).
void check_ply(const std::string& path, const std::string& text) {
  std::istringstream in(text);
  std::string line, element;
  for (int lineno = 1; std::getline(in, line); ++lineno) {
    std::istringstream words(line);
    std::string word, type, name;
    words >> word;
    if (word == "end_header") return;
    if (word == "element") {
      std::string count;
      words >> element >> count;
      long long n = -1;
      std::istringstream number(count);
      if (!(number >> n) || !number.eof() || n < 0 || n > static_cast<long long>(kMaxMeshTriangles) ||
          n > static_cast<long long>(text.size()))  // every element takes a byte at least
        fail(path, lineno, "element " + element + " has the count '" + count + "', not a whole number from 0 to " +
                               std::to_string(kMaxMeshTriangles));
    }
    if (word != "property") continue;
    if (element.empty()) fail(path, lineno, "a property before any element");
    words >> type >> name;
    if (type == "list") {  // name is the count's type: CGAL allocates what the count says
      const bool small = name == "uchar" || name == "uint8" || name == "char" || name == "int8" || name == "ushort" ||
                         name == "uint16" || name == "short" || name == "int16";
      if (!small) fail(path, lineno, "a list counted in " + name + ": up to 16 bits (uchar, ushort) are supported");
      continue;
    }
    for (std::string more; words >> more;) name = more;  // CGAL names a property by its last word
    const bool real = type == "float" || type == "double" || type == "float32" || type == "float64";
    if (element == "vertex" && (name == "x" || name == "y" || name == "z") && !real)
      fail(path, lineno, "vertex property " + name + " must be float or double, not " + type);
  }
}

}  // namespace

void check_mesh_file(const std::string& path) {
  const std::string ext = lowercase_extension(path);
  if (ext != ".off" && ext != ".ply") return;
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  if (ext == ".off") check_off(path, text);
  else check_ply(path, text);
}

}  // namespace mtcs::mesh
