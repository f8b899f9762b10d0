// The cavity temperature of one layout (what `mtcs thermal` prints): the same numbers as the
// pipeline's objectives, the heat balance closed, the finite volumes against FreeFem++, and the
// field on the cavity surface consistent with the samples.
#include <catch2/catch.hpp>
#include <iostream>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include "mtcs/eval/cavity_temperature.h"
#include "mtcs/eval/cavity_temperature_report.h"
#include "mtcs/eval/thermal_model.h"
#include "mtcs/eval/pipeline.h"
#include "mtcs/eval/thermal_tiers.h"
#include "mtcs/mold/decoder.h"
#include "mtcs/mold/layout_io.h"
#include "mtcs/thermal/line_sinks.h"
#include "support/scratch_file.h"
#include "support/paths.h"

using namespace mtcs;
using geometry::Vec3;

namespace {

const std::string kBlockSpec = MTCS_SOURCE_DIR + "/molds/thermal_block.yaml";
const std::string kBlockLayout = MTCS_SOURCE_DIR + "/molds/thermal_block.layout.yaml";

// The FreeFem++ P2 reference at the 720 patch samples: points and temperatures.
std::pair<std::vector<Vec3>, std::vector<double>> freefem() {
  std::ifstream in(MTCS_TEST_DATA + "/thermal/patch_samples.csv");
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
  // The extra points are the samples themselves here: the same values bit for bit (the extra
  // points and the field's vertices are evaluated apart from the samples, so neither moves the
  // samples' float origin or far-expansion chunks), and FreeFem's within the tier's error.
  REQUIRE(r.at_points.size() == 720);
  CHECK(r.at_points == r.at_samples);
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

// thermal.wall_images reaches the line-sink model both where the optimiser solves (the tier's
// solver) and where mtcs thermal does (cavity_temperature): each equals a model built with that
// many levels by hand, bit for bit, and differs from the default's.
TEST_CASE("cavity temperature: thermal.wall_images reaches the line sinks in the loop and in mtcs thermal", "[eval][thermal]") {
  mold::MoldSpec spec = mold::load_mold_spec(kBlockSpec);
  spec.thermal.wall_images = 1;
  const mold::Scene scene(spec);
  const mold::Layout layout = mold::decode(scene, mold::load_layout(kBlockLayout, spec));
  const thermal::Setting setting = eval::thermal_setting(scene);
  const thermal::Samples samples = eval::thermal_samples(scene);
  const std::vector<thermal::Channel> channels = eval::thermal_channels(layout, spec);
  REQUIRE_FALSE(spec.thermal.void_plane);  // the channels go to the model as they are
  auto by_hand = [&](int levels) {
    thermal::LineSinkOptions options;
    options.elements = spec.thermal.elements_per_bore;
    options.images = levels;
    thermal::LineSinkCache cache;
    return thermal::LineSinkModel(setting, samples, options).temperatures(channels, cache);
  };
  const std::vector<double> one = by_hand(1), two = by_hand(2);
  const std::vector<double> loop = eval::temperature_solver(spec.thermal.tier)(setting, samples, spec.thermal)(channels).temperature;
  const eval::CavityTemperature shown = eval::cavity_temperature(scene, layout, eval::thermal_query(spec));
  CHECK(loop == one);
  CHECK(shown.at_samples == one);
  double most = 0;
  for (std::size_t i = 0; i < one.size(); ++i) most = std::max(most, std::abs(one[i] - two[i]));
  CHECK(most > 1e-3);  // one level is another model: 0.24 K RMS against FreeFem++, two 0.14 K
  CHECK(most < 1.0);
}

TEST_CASE("cavity temperature: the heated surface's figures are those of its samples in the whole field", "[eval][thermal]") {
  // A box cavity whose top face (z >= 35) takes no heat: `heated` (the default) summarises the
  // 44 samples below z = 35, `all` the 68 (68 = 2 x (4 + 6 + 24) at 10 mm, as counted in
  // thermal_model_test). One bore along x under the cavity.
  const std::string text = "block: {box: {min: [0, 0, 0], max: [100, 100, 50]}}\n"
                           "cavity: {box: {min: [20, 20, 30], max: [80, 60, 36]}, sample_spacing: 10}\n"
                           "objectives: {use: [temperature_std, temperature_mean]}\n"
                           "thermal:\n  heat_flux: 20000\n"
                           "  regions: [{box: {min: [0, 0, 35], max: [100, 100, 50]}, heat_flux: 0}]\n";
  const auto dir = mtcs_test::scratch_dir("cavity_temperature");
  auto scene_of = [&](const std::string& name, const std::string& extra) {
    std::ofstream(dir / name) << text << extra;
    return mold::Scene(mold::load_mold_spec((dir / name).string()));
  };
  const mold::Scene heated = scene_of("heated.yaml", ""), all = scene_of("all.yaml", "  objective_surface: all\n");
  const mold::Layout layout = mold::decode(heated, mold::Genome{{{{{0, 40, 20}, {100, 40, 20}}, 8}}});
  const thermal::Samples every = eval::thermal_samples(all);
  REQUIRE(every.size() == 68);

  for (const auto tier : {mold::ThermalTier::T2d, mold::ThermalTier::Fd}) {
    eval::ThermalQuery q;
    q.tier = tier;
    q.cell = 5;
    const auto h = eval::cavity_temperature(heated, layout, q), a = eval::cavity_temperature(all, layout, q);
    CHECK(h.surface == "heated");
    CHECK(a.surface == "all");
    REQUIRE(h.at_samples.size() == 44);
    REQUIRE(a.at_samples.size() == 68);
    // The heated samples' area-weighted mean and std, straight from the whole field.
    double w = 0, mean = 0, var = 0, top = 0;
    for (std::size_t i = 0; i < 68; ++i)
      if (every.points[i].z() < 35) w += every.weights[i], mean += every.weights[i] * a.at_samples[i];
    mean /= w;
    for (std::size_t i = 0; i < 68; ++i)
      if (every.points[i].z() < 35) var += every.weights[i] * (a.at_samples[i] - mean) * (a.at_samples[i] - mean);
      else top = std::max(top, std::abs(a.at_samples[i] - mean));
    const double tolerance = tier == mold::ThermalTier::Fd ? 1e-9 : 1e-4;  // t2d: float columns
    CHECK(w == Approx(60 * 40 + 2 * (40 + 60) * 6).epsilon(1e-12));
    CHECK(h.summary.mean == Approx(mean).margin(tolerance));
    CHECK(h.summary.std == Approx(std::sqrt(var / w)).margin(tolerance));
    CHECK(top > 0);  // the top face differs: leaving it out matters
    CHECK(std::abs(h.summary.std - a.summary.std) > 10 * tolerance);
    if (tier == mold::ThermalTier::T2d) {
      // The optimiser's objectives cover the same surface.
      const auto e = eval::Pipeline(heated).evaluate(layout);
      CHECK(e.objectives[0] == Approx(h.summary.std).epsilon(1e-9));
      CHECK(e.objectives[1] == Approx(h.summary.mean).epsilon(1e-9));
    }
  }
  // `mtcs thermal --json` says which surface its figures cover.
  std::ostringstream json;
  eval::write_cavity_temperature_json(json, eval::cavity_temperature(heated, layout, eval::thermal_query(heated.spec())), std::cerr);
  CHECK(json.str().find("\"surface\": \"heated\"") != std::string::npos);
  CHECK(json.str().find("\"samples\": 44") != std::string::npos);
  std::filesystem::remove_all(dir);
}
