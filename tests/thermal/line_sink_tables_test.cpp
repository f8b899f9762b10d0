// Line-sink models of one setting share their tabulated heat input (line_sink_setup.cpp): a
// model built after another of the same setting gives the same temperatures bit for bit, and
// one of a changed setting does not pick up the earlier tables (a second method: the heat
// input summed exactly, without tables).
#include <catch2/catch.hpp>

#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <cmath>

#include "mtcs/thermal/line_sinks.h"

using namespace mtcs::thermal;
using mtcs::geometry::Segment;

namespace {

// The block case of block3d_case.txt (mm, W, degC), `flux` W/mm^2 on its patch.
Setting block_setting(double flux) {
  Setting s;
  s.block = {Vec3(0, 0, 0), Vec3(120, 80, 60)};
  s.conductivity = 0.03;
  for (auto& f : s.faces) f = {1e-5, 25};
  const Vec3 a(30, 16, 60), b(90, 16, 60), c(90, 64, 60), d(30, 64, 60);
  s.heat_in = {{a, b, c, flux}, {a, c, d, flux}};
  return s;
}

std::vector<Channel> bores() {
  std::vector<Channel> out;
  for (const auto& [y, z, d] : {std::array{20.0, 45.0, 10.0}, {40.0, 47.0, 8.0}, {61.0, 43.0, 10.0}}) {
    Channel c;
    c.axis = Segment{Vec3(0, y, z), Vec3(120, y, z)};
    c.radius = d / 2;
    c.coolant = 40;
    out.push_back(c);
  }
  return out;
}

Samples patch_points() {
  Samples s;
  for (double x = 35; x <= 85; x += 10)
    for (double y = 20; y <= 60; y += 10) s.points.push_back(Vec3(x, y, 60)), s.weights.push_back(1);
  return s;
}

std::vector<double> solve(const Setting& setting, const Samples& samples, LineSinkOptions options = {}) {
  const LineSinkModel model(setting, samples, options);
  LineSinkCache cache;
  return model.temperatures(bores(), cache);
}

}  // namespace

TEST_CASE("line sinks: models of one setting share their tables, a changed setting gets its own") {
  const Samples samples = patch_points();
  const std::vector<double> first = solve(block_setting(0.05), samples);
  const std::vector<double> again = solve(block_setting(0.05), samples);  // the kept tables
  CHECK(again == first);

  // A hotter patch right after: its own tables, as close to the exact sums as the first's are.
  LineSinkOptions exact;
  exact.heat_grid = 0;
  const std::vector<double> hot = solve(block_setting(0.08), samples);
  const std::vector<double> hot_exact = solve(block_setting(0.08), samples, exact);
  const std::vector<double> first_exact = solve(block_setting(0.05), samples, exact);
  double moved = 0, off = 0, off_first = 0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    moved = std::max(moved, std::abs(hot[i] - first[i]));
    off = std::max(off, std::abs(hot[i] - hot_exact[i]));
    off_first = std::max(off_first, std::abs(first[i] - first_exact[i]));
  }
  INFO("hotter patch moves the samples by " << moved << " K; tables against exact sums: " << off << " K (first: " << off_first << " K)");
  CHECK(moved > 1);
  CHECK(off < 0.05);
  CHECK(off <= 2 * off_first + 1e-9);
}

TEST_CASE("line sinks: the tables are the same built on one thread or on four") {
  // The grids' nodes are filled in parallel (line_sink_setup.cpp): each node's values its own.
  // (Where a node's values go is checked by the tables' accuracy: the case above, and the
  // FreeFem++ and closed-form tests of line_sinks_test.cpp.)
  const Samples samples = patch_points();
  std::vector<double> one, four;
  {
    const tbb::global_control serial(tbb::global_control::max_allowed_parallelism, 1);
    one = solve(block_setting(0.061), samples);
  }
  // Four other settings push the first out of the kept tables (the last four builds are kept),
  // so the next model builds its own.
  for (const double flux : {0.071, 0.072, 0.073, 0.074}) solve(block_setting(flux), samples);
  const tbb::global_control up_to_four(tbb::global_control::max_allowed_parallelism, 4);  // on 2 cores too
  tbb::task_arena arena(4);
  arena.execute([&] { four = solve(block_setting(0.061), samples); });
  REQUIRE(one.size() == samples.size());
  CHECK(four == one);
}
