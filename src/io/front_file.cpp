#include "mtcs/io/front_file.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "mtcs/io/input_error.h"

namespace mtcs::io {

FrontFile read_front(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, 0, "", "cannot open file");
  FrontFile f;
  std::string line;
  int lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    std::istringstream ss(line);
    std::string first;
    if (!(ss >> first)) continue;
    const bool ref_line = first == "#";
    if (first[0] == '#' && !ref_line) continue;
    if (ref_line) {
      std::string word;
      if (!(ss >> word) || word != "ref") continue;  // other comments
    } else {
      ss.clear();
      ss.str(line);
    }
    std::vector<double> p;
    std::string tok;
    int column = 1;
    while (ss >> tok) {
      const std::size_t at = line.find(tok, std::size_t(column - 1));
      column = int(at) + 1;
      char* end = nullptr;
      const double v = std::strtod(tok.c_str(), &end);
      if (end != tok.c_str() + tok.size() || !std::isfinite(v))
        throw InputError(path, lineno, column, ref_line ? "ref" : "point", "expected a number, got '" + tok + "'");
      p.push_back(v);
      column += int(tok.size());
    }
    if (ref_line) {
      f.ref = p;
    } else {
      if (!f.points.empty() && p.size() != f.points.front().size())
        throw InputError(path, lineno, 1, "point", "has " + std::to_string(p.size()) + " coordinates, the first point " +
                                                           std::to_string(f.points.front().size()));
      f.points.push_back(p);
    }
  }
  return f;
}

}  // namespace mtcs::io
