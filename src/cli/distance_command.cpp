// mtcs distance: the cylinder kernel over a CSV of pairs.

#include <CLI/CLI.hpp>
#include <cmath>
#include <memory>

#include "mtcs/io/atomic_file.h"
#include "mtcs/cli/commands.h"
#include "mtcs/io/pairs_csv.h"
#include "mtcs/geometry/cylinder_distance.h"
#include "number_checks.h"

namespace mtcs::cli {

using io::AtomicFile;
using io::read_pairs_csv;

Command add_distance_command(CLI::App& app) {
  struct Options {
    std::string pairs, out;
    double upper_bound = std::numeric_limits<double>::infinity();
    double tolerance = 1e-12;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand(
      "distance",
      "Exact distance between solid cylinders, for every pair in a CSV.\n"
      "Input columns (by header name, extra columns ignored):\n"
      "  id,p0x,p0y,p0z,p1x,p1y,p1z,r0,q0x,q0y,q0z,q1x,q1y,q1z,r1\n"
      "Output: id,distance,feature,bounded  (bounded=1: only distance >= U was proved;\n"
      "feature: shell-shell, shell-rim, rim-disk, rim-rim, disk-disk, intersecting, bounded).\n"
      "Example: mtcs distance --pairs pairs.csv --out d.csv --upper-bound 5");
  sub->add_option("--pairs", opt->pairs, "input CSV of cylinder pairs")->required()->check(CLI::ExistingFile);
  sub->add_option("--out", opt->out, "output CSV (written whole or not at all)")->required();
  sub->add_option("--upper-bound", opt->upper_bound,
                  "U: distances >= U may stop early and be reported as bounded (default: none)")
      ->check(positive_number());
  sub->add_option("--tolerance", opt->tolerance,
                  "target error of the numerical parts, relative to max(1, pair scale)")->capture_default_str()
      ->check(CLI::Range(1e-18, 1.0));

  return {sub, [opt] {
            const auto pairs = read_pairs_csv(opt->pairs);
            geometry::DistanceRequest request;
            request.upper_bound = opt->upper_bound;
            request.tolerance = opt->tolerance;
            AtomicFile file(opt->out);
            auto& out = file.stream();
            out << "id,distance,feature,bounded\n";
            for (const auto& p : pairs) {
              const auto r = geometry::distance(p.a, p.b, request);
              out << p.id << ',' << r.distance << ',' << geometry::to_string(r.feature) << ','
                  << (r.bounded ? 1 : 0) << '\n';
            }
            file.commit();
            return 0;
          }};
}

}  // namespace mtcs::cli
