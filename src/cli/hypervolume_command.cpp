// mtcs hypervolume: the exact hypervolume of a front, and optionally every point's exclusive
// contribution, in the format of shared/cases/hv_fronts (one point per line, "# ref r1 r2 ...").

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

#include "mtcs/cli/commands.h"
#include "mtcs/io/input_error.h"
#include "mtcs/opt/hypervolume.h"

namespace mtcs::cli {
namespace {

struct Front {
  std::vector<opt::Point> points;
  opt::Point ref;
};

Front read_front(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw io::InputError(path, 0, 0, "", "cannot open file");
  Front f;
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
    opt::Point p;
    std::string tok;
    int column = 1;
    while (ss >> tok) {
      const std::size_t at = line.find(tok, std::size_t(column - 1));
      column = int(at) + 1;
      char* end = nullptr;
      const double v = std::strtod(tok.c_str(), &end);
      if (end != tok.c_str() + tok.size() || !std::isfinite(v))
        throw io::InputError(path, lineno, column, ref_line ? "ref" : "point", "expected a number, got '" + tok + "'");
      p.push_back(v);
      column += int(tok.size());
    }
    if (ref_line) {
      f.ref = p;
    } else {
      if (!f.points.empty() && p.size() != f.points.front().size())
        throw io::InputError(path, lineno, 1, "point", "has " + std::to_string(p.size()) + " coordinates, the first point " +
                                                           std::to_string(f.points.front().size()));
      f.points.push_back(p);
    }
  }
  return f;
}

}  // namespace

Command add_hypervolume_command(CLI::App& app) {
  struct Options {
    std::string front;
    std::vector<double> ref;
    bool contributions = false;
  };
  auto o = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand(
      "hypervolume",
      "Exact hypervolume of a front (minimisation), printed alone on the first line (17 digits);\n"
      "with --contributions, then each point's exclusive contribution, one per line, in input order.\n"
      "FRONT: one point per line, whitespace-separated; a first line '# ref r1 r2 ...' gives the\n"
      "reference point unless --ref does. Example: mtcs hypervolume front.txt --contributions");
  sub->add_option("front", o->front, "front file")->required();
  sub->add_option("--ref", o->ref, "reference point r1,r2,...")->delimiter(',');
  sub->add_flag("--contributions", o->contributions, "also print every point's exclusive contribution");
  return {sub, [o] {
            Front f = read_front(o->front);
            if (!o->ref.empty()) f.ref = o->ref;
            if (f.ref.empty()) throw io::InputError(o->front, 1, 1, "ref", "no reference point: add '# ref ...' or --ref");
            if (!f.points.empty() && f.points.front().size() != f.ref.size())
              throw io::InputError(o->front, 1, 1, "ref", "the reference point has " + std::to_string(f.ref.size()) +
                                                                " coordinates, the points " + std::to_string(f.points.front().size()));
            std::printf("%.17g\n", opt::hypervolume(f.points, f.ref));
            if (o->contributions)
              for (const double c : opt::contributions(f.points, f.ref)) std::printf("%.17g\n", c);
            return 0;
          }};
}

}  // namespace mtcs::cli
