// The cavity temperature of one layout (what `mtcs thermal` prints): the same numbers as the
// pipeline's objectives, the heat balance closed, the finite volumes against FreeFem++, and the
// field on the cavity surface consistent with the samples.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "mtcs/eval/cavity_temperature.h"
#include "mtcs/eval/pipeline.h"
#include "mtcs/mold/decoder.h"
#include "mtcs/mold/layout_io.h"

using namespace mtcs;
using geometry::Vec3;

namespace {

const char* kBlockSpec = MTCS_SOURCE_DIR "/molds/thermal_block.yaml";
const char* kBlockLayout = MTCS_SOURCE_DIR "/molds/thermal_block.layout.yaml";

// The FreeFem++ P2 reference at the 720 patch samples: points and temperatures.
std::pair<std::vector<Vec3>, std::vector<double>> freefem() {
  std::ifstream in(MTCS_TEST_DATA "/thermal/patch_samples.csv");
  std::string line;
  std::getline(in, line);
  std::vector<Vec3> p;
  std::vector<double> t;
  double x, y, z, v;
  char c;
  while (in >> x >> c >> y >> c >> z >> c >> v) p.emplace_back(x, y, z), t.push_back(v);
  return {p, t};
}

double rms(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0;
  for (std::size_t i = 0; i < a.size(); ++i) s += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(s / double(a.size()));
}

}  // namespace

TEST_CASE("cavity temperature: the objectives' numbers, a closed balance, points and a field", "[eval][thermal]") {
  const mold::Scene scene(mold::load_mold_spec(kBlockSpec));
  const mold::Layout layout = mold::decode(scene, mold::load_layout(kBlockLayout, scene.spec()));
  const auto [points, reference] = freefem();
  const auto r = eval::cavity_temperature(scene, layout, eval::thermal_query(scene.spec()), points, 4.0);
  CHECK(r.tier == "t2d");
  // The pipeline scores temperature_std and temperature_max from the same tier.
  const auto e = eval::Pipeline(scene).evaluate(layout);
  CHECK(r.summary.std == Approx(e.objectives[0]).epsilon(1e-9));
  CHECK(r.summary.max == Approx(e.objectives[1]).epsilon(1e-9));
  // 144 W in, all of it out through the bores and the faces.
  CHECK(r.balance.in == Approx(144).epsilon(1e-9));
  CHECK(std::abs(r.balance.residual()) < 1e-6);
  // The extra points are the samples themselves here: the same values, and FreeFem's within the
  // tier's error.
  REQUIRE(r.at_points.size() == 720);
  CHECK(rms(r.at_points, r.at_samples) < 1e-4);  // float columns at the samples
  CHECK(rms(r.at_points, reference) < 0.2);
  // The field spans the samples' range (its vertices include the patch's edges and corners,
  // which run cooler than the nearest samples).
  REQUIRE(r.field.values.size() == r.field.surface.vertices.size());
  CHECK(r.field.surface.vertices.size() > 300);
  const auto [lo, hi] = std::minmax_element(r.field.values.begin(), r.field.values.end());
  CHECK(*hi == Approx(r.summary.max).margin(0.2));
  CHECK(*lo < *std::min_element(r.at_samples.begin(), r.at_samples.end()));
}

TEST_CASE("cavity temperature: finite volumes at 2 mm against FreeFem++", "[eval][thermal]") {
  const mold::Scene scene(mold::load_mold_spec(kBlockSpec));
  const mold::Layout layout = mold::decode(scene, mold::load_layout(kBlockLayout, scene.spec()));
  const auto [points, reference] = freefem();
  eval::ThermalQuery q;
  q.tier = mold::ThermalTier::Fd;
  q.cell = 2;
  const auto r = eval::cavity_temperature(scene, layout, q, points);
  CHECK(r.tier == "fd");
  CHECK(rms(r.at_points, reference) < 0.25);  // experiments/thermal/fv.md: 0.18 K at 2 mm
  CHECK(std::abs(r.balance.residual()) < 1e-6 * r.balance.in);
  CHECK(r.balance.to_channels == Approx(137.82).margin(0.05));  // FreeFem: 137.82 W
}
