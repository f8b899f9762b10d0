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
#include "mtcs/io/front_file.h"
#include "mtcs/io/input_error.h"
#include "mtcs/opt/hypervolume.h"

namespace mtcs::cli {

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
            io::FrontFile f = io::read_front(o->front);
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
