// The coupled cavity against an independent solver: FreeFem++ 3-D (tetgen, P2) on the bundled
// cup's, gear's and L-bracket's blocks and parts, with Robin bores, the part's film on the
// cavity and convecting faces (experiments/thermal/freefem_coupled: its scripts, meshes,
// convergence). The stored samples against T3 and the spec's line-sink tier on the same problem.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <sstream>

#include "mtcs/eval/thermal_model.h"
#include "mtcs/mold/scene.h"
#include "mtcs/thermal/finite_volume.h"
#include "mtcs/thermal/line_sinks.h"
#include "support/bundled_variant.h"
#include "support/paths.h"

using namespace mtcs;
using geometry::Vec3;

namespace {

std::vector<std::vector<double>> read_rows(const std::string& path) {
  std::ifstream in(path);
  REQUIRE(in);
  std::string line;
  std::getline(in, line);  // the header
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::vector<double> row;
    std::string cell;
    while (std::getline(s, cell, ',')) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

// The channels FreeFem++ solved with: closed cylinders inside the block (radius, film, coolant).
std::vector<thermal::Channel> stored_channels(const std::string& mold) {
  std::vector<thermal::Channel> out;
  for (const auto& r : read_rows(MTCS_TEST_DATA + "/thermal/freefem_coupled_" + mold + "_channels.csv"))
    out.push_back({geometry::Segment{Vec3(r[0], r[1], r[2]), Vec3(r[3], r[4], r[5])}, r[6], r[8], r[7] * 1e-6});
  return out;
}

struct Errors {
  double rms = 0, max = 0, mean_bias = 0;
};

Errors against(const std::vector<double>& ours, const std::vector<std::vector<double>>& reference) {
  Errors e;
  for (std::size_t i = 0; i < ours.size(); ++i) {
    const double d = ours[i] - reference[i][3];
    e.rms += d * d, e.max = std::max(e.max, std::abs(d)), e.mean_bias += d;
  }
  e.rms = std::sqrt(e.rms / double(ours.size())), e.mean_bias /= double(ours.size());
  return e;
}

const char* const kLocalWall = "wall_thickness: local  # from the mesh: each place its own wall, corners and bosses thicker";

// T3 at 2 mm and the spec's line-sink tier against FreeFem++'s samples of `mold`, cooled by the
// channels FreeFem++ had.
struct Compared {
  Errors t3, line_sinks;
  double void_panel = 0;
};
Compared against_freefem(const mold::Scene& scene, const std::string& mold) {
  const auto reference = read_rows(MTCS_TEST_DATA + "/thermal/freefem_coupled_" + mold + ".csv");
  // At FreeFem++'s own points (the cavity samples of the day: points of the cavity's surface),
  // whatever the sampler makes of the part now.
  thermal::Samples samples;
  for (const auto& r : reference) samples.points.emplace_back(r[0], r[1], r[2]), samples.weights.push_back(1);
  REQUIRE(samples.size() > 1000);
  for (const Vec3& p : samples.points)  // on this part's surface (the CSV's 6 decimals)
    REQUIRE(scene.cavity_bvh()->segment_distance(p, p, 1) < 1e-5);
  const thermal::Model model{eval::thermal_setting(scene), stored_channels(mold)};
  const thermal::FvResult fv = thermal::solve_finite_volume(model, samples, {2.0});
  thermal::LineSinkOptions options;
  options.void_panel = scene.spec().thermal.void_panel;
  thermal::LineSinkCache cache;
  const std::vector<double> ls = thermal::LineSinkModel(model.setting, samples, options).temperatures(model.channels, cache);
  return {against(fv.temperature, reference), against(ls, reference), options.void_panel};
}

std::string describe(const Compared& c) {
  std::ostringstream s;
  s << "T3 at 2 mm: RMS " << c.t3.rms << " K, max " << c.t3.max << " K, bias " << c.t3.mean_bias << " K; t2d (void "
    << c.void_panel << " mm): RMS " << c.line_sinks.rms << ", max " << c.line_sinks.max << ", bias " << c.line_sinks.mean_bias;
  return s.str();
}

}  // namespace

TEST_CASE("coupled cavity: the cup's samples as FreeFem++ P2 has them", "[eval][coupling]") {
  // FreeFem++ ran the cup at one 2.5 mm wall (the bundled cup now takes its walls from the mesh).
  const mold::Scene scene(mold::load_mold_spec(mtcs_test::bundled_variant("cup", kLocalWall, "wall_thickness: 2.5")));
  const Compared c = against_freefem(scene, "cup");
  INFO(describe(c));
  // Measured: T3 at 2 mm RMS 0.64 K (max 2.6 K); at 1 mm 0.42 K (max 2.2 K, 100 s: not here);
  // t2d with the void's 12 mm panels 2.36 K (max 13.9 K, at the core's corners).
  CHECK(c.t3.rms < 0.8);
  CHECK(c.line_sinks.rms < 3.0);
}

TEST_CASE("coupled cavity: the gear's samples as FreeFem++ P2 has them", "[eval][coupling]") {
  // FreeFem++ solved the gear (5 mm wall) with the film its problem JSON gave: the same here
  // by the explicit override, whatever the bundled cycle derives.
  const mold::Scene scene(mold::load_mold_spec(mtcs_test::bundled_variant(
      "gear", "cavity_condition: coupled", "cavity_condition: coupled\n  part_film: 88.0344028649008\n  part_temperature: 230")));
  const Compared c = against_freefem(scene, "gear");
  INFO(describe(c));
  // Measured: T3 at 2 mm RMS 1.33 K (max 9.0 K, the teeth's staircase), t2d with the void's
  // 8 mm panels 0.61 K (max 2.4 K); against the coarse P2 (0.008 K from the fine one) T3 at
  // 1.5 mm 0.56 K, at 1 mm 0.79 K (max 5.7 K: not converging on the teeth; minutes, not here).
  // On this part the line sinks beat the grid.
  CHECK(c.t3.rms < 1.6);
  CHECK(c.line_sinks.rms < 0.8);
}

TEST_CASE("coupled cavity: the L-bracket's samples as FreeFem++ P2 has them", "[eval][coupling]") {
  // FreeFem++ solved the bracket at one 6 mm wall with the film its problem JSON gave (the
  // cycle's fixed point for that wall): the same here by the explicit override.
  const mold::Scene scene(mold::load_mold_spec(mtcs_test::bundled_variant(
      "l_bracket", {{kLocalWall, "wall_thickness: 6"},
                    {"cavity_condition: coupled",
                     "cavity_condition: coupled\n  part_film: 76.92727490677034\n  part_temperature: 230"}})));
  const Compared c = against_freefem(scene, "l_bracket");
  INFO(describe(c));
  // Measured: T3 at 2 mm RMS 0.10 K (max 0.37 K), at 1 mm 0.08 K (max 0.17 K, 110 s: not here);
  // t2d with the void's 12 mm panels 0.42 K (max 4.0 K, at the inner corner). A part of flat
  // faces the grid draws well: the FreeFem++ levels agree to 0.012 K.
  CHECK(c.t3.rms < 0.2);
  CHECK(c.line_sinks.rms < 0.6);
}
