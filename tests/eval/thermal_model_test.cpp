// The thermal model built from a scene and a layout: the reference block's heat input, films
// and conductivity against block3d_case.txt, its samples against the 720 points of the FEM
// reference, channels against the case's bores, and through-bores that are legal.

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include <unistd.h>

#include "../support/scratch_file.h"
#include "mtcs/eval/coolant.h"
#include "mtcs/eval/cycle_time.h"
#include "mtcs/eval/pipeline.h"
#include "mtcs/eval/thermal_model.h"
#include "mtcs/mold/decoder.h"
#include "mtcs/mold/layout_io.h"
#include "support/paths.h"

using namespace mtcs;
using geometry::Vec3;
namespace fs = std::filesystem;

namespace {

fs::path write(const std::string& name, const std::string& text) {
  return mtcs_test::write_scratch("thermal_model_test", name, text);
}

const std::string kBlockSpec = MTCS_SOURCE_DIR + "/molds/thermal_block.yaml";
const std::string kBlockLayout = MTCS_SOURCE_DIR + "/molds/thermal_block.layout.yaml";

Vec3 normal(const thermal::HeatedTriangle& t) { return (t.b - t.a).cross(t.c - t.a); }
double area(const thermal::HeatedTriangle& t) { return normal(t).norm() / 2; }
double heat(const thermal::Setting& s) {
  double q = 0;
  for (const auto& t : s.heat_in) q += t.flux * area(t);
  return q;
}

// The reference block with extra lines appended to its spec.
std::string block_spec(const std::string& extra) {
  std::ifstream in(kBlockSpec);
  std::stringstream ss;
  ss << in.rdbuf();
  std::string text = ss.str();
  const auto at = text.find("thermal:\n");
  return text.substr(0, at) + extra + text.substr(text.find("objectives:"));
}

}  // namespace

TEST_CASE("thermal model: the reference block's setting is block3d_case.txt", "[eval][thermal]") {
  const mold::Scene scene(mold::load_mold_spec(kBlockSpec));
  const thermal::Setting s = eval::thermal_setting(scene);
  CHECK(s.block.min == Vec3(0, 0, 0));
  CHECK(s.block.max == Vec3(120, 80, 60));
  CHECK(s.conductivity == Approx(0.03).epsilon(1e-15));  // 30 W/(m K)
  for (const auto& f : s.faces) {
    CHECK(f.film == Approx(1e-5).epsilon(1e-15));  // 10 W/(m^2 K)
    CHECK(f.ambient == 25);
  }
  // A patch on the face: no void.
  CHECK_FALSE(s.cavity_box);
  CHECK_FALSE(s.cavity_mesh);
  // 0.05 W/mm^2 on 60 x 48 mm: 144 W, entering from above (+z).
  CHECK(heat(s) == Approx(0.05 * 2880).epsilon(1e-12));
  for (const auto& t : s.heat_in) {
    CHECK(t.flux == Approx(0.05).epsilon(1e-15));
    CHECK(normal(t).normalized().z() == Approx(1));
    for (const Vec3& p : {t.a, t.b, t.c}) {
      CHECK(p.z() == 60);
      CHECK((p.x() >= 30 && p.x() <= 90 && p.y() >= 16 && p.y() <= 64));
    }
  }
}

TEST_CASE("thermal model: the patch samples are the 720 points of the FEM reference", "[eval][thermal]") {
  const mold::Scene scene(mold::load_mold_spec(kBlockSpec));
  const thermal::Samples samples = eval::thermal_samples(scene);
  std::ifstream in(MTCS_TEST_DATA + "/thermal/patch_samples.csv");
  std::string line;
  std::getline(in, line);
  REQUIRE(line == "x,y,z,T");
  std::vector<Vec3> expected;
  while (std::getline(in, line)) {
    double x, y, z;
    REQUIRE(std::sscanf(line.c_str(), "%lf,%lf,%lf", &x, &y, &z) == 3);
    expected.emplace_back(x, y, z);
  }
  REQUIRE(expected.size() == 720);
  REQUIRE(samples.size() == 720);
  for (std::size_t i = 0; i < 720; ++i) {
    CHECK(samples.points[i] == expected[i]);  // same points, same order (x fastest)
    CHECK(samples.weights[i] == 4);           // 2 x 2 mm each
  }
  // The tier-0 pipeline samples the same points.
  CHECK(eval::Pipeline(scene).surface_samples() == 720);
}

TEST_CASE("thermal model: regions cut the heat input, defaults derive from the part", "[eval][thermal]") {
  // The left half of the patch (x < 60) at 80 kW/m^2, the rest at 50 kW/m^2.
  const mold::Scene scene(mold::load_mold_spec(
      write("regions.yaml", block_spec("thermal:\n  heat_flux: 50000\n  regions:\n"
                                       "    - {box: {min: [0, 0, 59], max: [60, 80, 61]}, heat_flux: 80000}\n"))
          .string()));
  const thermal::Setting s = eval::thermal_setting(scene);
  CHECK(heat(s) == Approx(0.08 * 30 * 48 + 0.05 * 30 * 48).epsilon(1e-12));
  for (const auto& t : s.heat_in) {
    const double cx = (t.a.x() + t.b.x() + t.c.x()) / 3;
    CHECK(t.flux == Approx(cx < 60 ? 0.08 : 0.05).epsilon(1e-15));
  }
  // Without heat_flux: the default from the polymer and the wall thickness.
  const mold::Scene plain(mold::load_mold_spec(write("default.yaml", block_spec("")).string()));
  CHECK(eval::cavity_heat_flux(plain.spec()) == eval::default_heat_flux(plain.spec()));
  CHECK(heat(eval::thermal_setting(plain)) == Approx(eval::default_heat_flux(plain.spec()) * 2880).epsilon(1e-12));
}

TEST_CASE("thermal model: a box cavity is a void heated from inside", "[eval][thermal]") {
  const mold::Scene scene(mold::load_mold_spec(
      write("box.yaml", "block: {box: {min: [0, 0, 0], max: [300, 200, 120]}}\n"
                        "cavity: {box: {min: [50, 25, 105], max: [250, 175, 108]}}\n"
                        "thermal: {heat_flux: 20000, adiabatic_faces: [-z, +x]}\n")
          .string()));
  const thermal::Setting s = eval::thermal_setting(scene);
  REQUIRE(s.cavity_box);
  CHECK(s.cavity_box->min == Vec3(50, 25, 105));
  const double surface = 2 * (200 * 150 + 200 * 3 + 150 * 3);
  CHECK(heat(s) == Approx(0.02 * surface).epsilon(1e-12));
  const Vec3 centre(150, 100, 106.5);
  for (const auto& t : s.heat_in) CHECK(normal(t).dot(centre - t.a) > 0);  // faces the melt inside
  // Faces -x, +x, -y, +y, -z, +z: -z and +x adiabatic.
  CHECK(s.faces[std::size_t(thermal::BlockFace::NegZ)].film == 0);
  CHECK(s.faces[std::size_t(thermal::BlockFace::PosX)].film == 0);
  CHECK(s.faces[std::size_t(thermal::BlockFace::NegX)].film == Approx(1e-5));
  CHECK(s.faces[std::size_t(thermal::BlockFace::PosZ)].film == Approx(1e-5));
}

TEST_CASE("thermal model: the heated surface is the samples where heat enters", "[eval][thermal]") {
  // A 60 x 40 x 6 mm box cavity sampled every 10 mm: per face x = 20, 80: 4 (y) x 1 (z); y = 20,
  // 60: 1 (z) x 6 (x); z = 30, 36: 6 (x) x 4 (y). 68 samples. No flux into the top face (z >= 35)
  // nor the -x face (x <= 20): 24 + 4 left out, 40 heated, of area 60 x 40 + 40 x 6 + 2 x 60 x 6.
  const std::string cavity = "block: {box: {min: [0, 0, 0], max: [100, 100, 50]}}\n"
                             "cavity: {box: {min: [20, 20, 30], max: [80, 60, 36]}, sample_spacing: 10}\n";
  const std::string regions = "  regions: [{box: {min: [0, 0, 35], max: [100, 100, 50]}, heat_flux: 0},\n"
                              "            {box: {min: [0, 0, 0], max: [20, 100, 50]}, heat_flux: 0}]\n";
  auto samples = [&](const std::string& name, const std::string& thermal) {
    return eval::thermal_samples(mold::Scene(mold::load_mold_spec(write(name, cavity + thermal).string())));
  };
  auto total = [](const thermal::Samples& s) {
    double a = 0;
    for (double w : s.weights) a += w;
    return a;
  };
  const thermal::Samples heated = samples("heated.yaml", "thermal:\n  heat_flux: 20000\n" + regions);
  REQUIRE(heated.size() == 40);
  CHECK(total(heated) == Approx(60 * 40 + 40 * 6 + 2 * 60 * 6).epsilon(1e-12));
  int lower = 0;
  for (const Vec3& p : heated.points) {
    CHECK(p.z() < 35);
    CHECK(p.x() > 20);
    lower += p.z() == 30;
  }
  CHECK(lower == 24);
  // `all`: every sample; no heated sample at all: every sample too.
  const thermal::Samples all = samples("all.yaml", "thermal:\n  heat_flux: 20000\n  objective_surface: all\n" + regions);
  CHECK(all.size() == 68);
  CHECK(total(all) == Approx(2 * (60 * 40 + 40 * 6 + 60 * 6)).epsilon(1e-12));
  CHECK(samples("cold.yaml", "thermal:\n  heat_flux: 0\n").size() == 68);
}

TEST_CASE("thermal model: thermal.sample_spacing coarsens the samples, not their area", "[eval][thermal]") {
  // The cavity of the case above at 20 mm: x faces 2 (y) x 1 (z), y faces 1 (z) x 3 (x), z faces
  // 3 (x) x 2 (y): 22 samples; without the top (6) and the -x face (2): 14 heated, of the same
  // area as at 10 mm.
  const std::string cavity = "block: {box: {min: [0, 0, 0], max: [100, 100, 50]}}\n"
                             "cavity: {box: {min: [20, 20, 30], max: [80, 60, 36]}, sample_spacing: 10}\n"
                             "thermal:\n  heat_flux: 20000\n"
                             "  regions: [{box: {min: [0, 0, 35], max: [100, 100, 50]}, heat_flux: 0},\n"
                             "            {box: {min: [0, 0, 0], max: [20, 100, 50]}, heat_flux: 0}]\n";
  auto samples = [&](const std::string& name, const std::string& thermal) {
    return eval::thermal_samples(mold::Scene(mold::load_mold_spec(write(name, cavity + thermal).string())));
  };
  auto total = [](const thermal::Samples& s) {
    double a = 0;
    for (double w : s.weights) a += w;
    return a;
  };
  const thermal::Samples coarse = samples("coarse.yaml", "  sample_spacing: 20\n");
  REQUIRE(coarse.size() == 14);
  CHECK(total(coarse) == Approx(60 * 40 + 40 * 6 + 2 * 60 * 6).epsilon(1e-12));
  for (const Vec3& p : coarse.points) CHECK((p.z() == 30 ? (p.x() == 30 || p.x() == 50 || p.x() == 70) : true));
  CHECK(samples("all.yaml", "  sample_spacing: 20\n  objective_surface: all\n").size() == 22);
  // The key at the cavity's spacing: the same samples, bit for bit.
  const thermal::Samples same = samples("same.yaml", "  sample_spacing: 10\n"), fine = samples("fine.yaml", "");
  CHECK(same.points == fine.points);
  CHECK(same.weights == fine.weights);
}

TEST_CASE("thermal model: a mesh cavity's triangles face the melt inside the part", "[eval][thermal]") {
  write("tet.off", "OFF\n4 4 0\n0 0 0\n10 0 0\n0 10 0\n0 0 10\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  const mold::Scene scene(mold::load_mold_spec(
      write("tet.yaml", "block: {box: {min: [0, 0, 0], max: [100, 100, 50]}}\n"
                        "cavity: {mesh: tet.off, translate: [40, 40, 20]}\n"
                        "thermal: {heat_flux: 10000}\n")
          .string()));
  const thermal::Setting s = eval::thermal_setting(scene);
  REQUIRE(s.cavity_mesh);
  REQUIRE(s.heat_in.size() == 4);
  const Vec3 centre = Vec3(40, 40, 20) + Vec3(2.5, 2.5, 2.5);
  for (const auto& t : s.heat_in) CHECK(normal(t).dot(centre - t.a) > 0);
  CHECK(heat(s) == Approx(0.01 * (3 * 50 + std::sqrt(3.0) / 4 * 200)).epsilon(1e-12));  // 3 legs + the slanted face
}

TEST_CASE("thermal model: the reference layout's channels are the case's bores B1-B3", "[eval][thermal]") {
  const mold::Scene scene(mold::load_mold_spec(kBlockSpec));
  const auto layout = mold::decode(scene, mold::load_layout(kBlockLayout, scene.spec()));
  const auto channels = eval::thermal_channels(layout, scene.spec());
  // block3d_case.txt: {p0: [0, y, z], p1: [120, y, z], diameter}, walls Dirichlet at 40 C.
  const double bores[3][3] = {{20, 45, 10}, {40, 47, 8}, {61, 43, 10}};
  REQUIRE(channels.size() == 3);
  for (std::size_t b = 0; b < 3; ++b) {
    CHECK(channels[b].axis.p0 == Vec3(0, bores[b][0], bores[b][1]));
    CHECK(channels[b].axis.p1 == Vec3(120, bores[b][0], bores[b][1]));
    CHECK(channels[b].radius == bores[b][2] / 2);
    CHECK(channels[b].coolant == 40);
    CHECK(std::isinf(channels[b].film));
  }
  // A film, or a flow rate through each bore's own diameter.
  mold::MoldSpec spec = scene.spec();
  spec.thermal.coolant_film = 5e-3;
  CHECK(eval::thermal_channels(layout, spec)[1].film == 5e-3);
  spec.thermal.coolant_film.reset();
  spec.thermal.flow_rate = 8;
  const auto flowing = eval::thermal_channels(layout, spec);
  CHECK(flowing[0].film == eval::coolant_film(8, 10, 40));
  CHECK(flowing[1].film == eval::coolant_film(8, 8, 40));
}

TEST_CASE("thermal model: channels leave out plugged dead ends and drill points", "[eval][thermal]") {
  const mold::Scene scene(mold::load_mold_spec(MTCS_SOURCE_DIR + "/molds/plate.yaml"));
  const auto layout = mold::decode(scene, mold::load_layout(MTCS_SOURCE_DIR + "/molds/plate.layout.yaml", scene.spec()));
  const auto channels = eval::thermal_channels(layout, scene.spec());
  REQUIRE(channels.size() == layout.bores.size());
  int plugged = 0;
  for (std::size_t b = 0; b < channels.size(); ++b) {
    const auto& bore = layout.bores[b];
    CHECK(channels[b].axis.p0 == bore.flow_start);
    CHECK(channels[b].axis.p1 == bore.flow_end);
    if (bore.plugged) {
      ++plugged;
      // The cross hole of a U loop, entered from a side face: its flow starts past the plug.
      CHECK((channels[b].axis.p0 - channels[b].axis.p1).norm() < bore.drilled_length);
    }
  }
  CHECK(plugged == 3);
}

TEST_CASE("through-bores: the reference layout is feasible", "[eval][thermal]") {
  const mold::Scene scene(mold::load_mold_spec(kBlockSpec));
  const eval::Pipeline pipeline(scene);
  const auto e = pipeline.evaluate(mold::load_layout(kBlockLayout, scene.spec()));
  for (const auto& v : e.violations) FAIL_CHECK(eval::to_string(v.kind) << " " << v.elements[0] << " " << v.distance);
  CHECK(e.feasible());
}

TEST_CASE("through-bores: a bore ending just under a face elsewhere is still flagged", "[eval][thermal]") {
  // Along y through a 300 x 200 x 120 block, inlet on -y and outlet on +y.
  const mold::Scene scene(mold::load_mold_spec(
      write("through.yaml", "block: {box: {min: [0, 0, 0], max: [300, 200, 120]}}\n"
                            "drilling: {diameters: [8], allowed_faces: [+y, -y]}\n"
                            "circuits: {inlet_faces: [-y], outlet_faces: [+y]}\n"
                            "clearances: {bore_surface: 3}\n"
                            "objectives: {use: [cost]}\n")
          .string()));
  const eval::Pipeline pipeline(scene);
  auto surface = [&](const mold::Genome& g) {
    int n = 0;
    for (const auto& v : pipeline.evaluate(g).violations) n += v.kind == eval::ViolationKind::BoreSurface;
    return n;
  };
  // Open at both ports: legal.
  CHECK(surface(mold::Genome{{{{{150, 0, 60}, {150, 200, 60}}, 8}}}) == 0);
  // The outlet 1 mm short of the +y face: not a port on its face, the hole ends 1 mm under it.
  CHECK(surface(mold::Genome{{{{{150, 0, 60}, {150, 199, 60}}, 8}}}) == 1);
  // A U loop whose far legs end (drill point included) 2.6 mm under +y: flagged, the legs'
  // open entries on -y are not.
  mold::Genome u{{{{{100, 0, 60}, {100, 195, 60}, {130, 195, 60}, {130, 0, 60}}, 8}}};
  const auto layout = mold::decode(scene, u);
  CHECK_FALSE(layout.bores[0].through);
  CHECK(surface(u) >= 2);
  // Sideways, a through-bore 2 mm from the -x face is flagged along its length.
  CHECK(surface(mold::Genome{{{{{6, 0, 60}, {6, 200, 60}}, 8}}}) == 1);
}

TEST_CASE("temperature objectives: the pipeline asks the tier's solver and summarises", "[eval][thermal]") {
  const std::string text = block_spec("thermal: {heat_flux: 50000}\n");
  const std::string use = "  use: [temperature_std, temperature_max, cost]";
  const auto at = text.find(use);
  REQUIRE(at != std::string::npos);
  const std::string spec_text = text.substr(0, at) + "  use: [temperature_std, cost, temperature_mean, temperature_max, cycle_time]" +
                                text.substr(at + use.size());
  const mold::Scene scene(mold::load_mold_spec(write("physics.yaml", spec_text).string()));
  // A stand-in tier: T = 40 + 0.1 x + (number of channels), so that the summary has a closed form.
  int built = 0;
  const eval::TemperatureSolverFactory factory = [&built](const thermal::Setting& setting, const thermal::Samples& samples,
                                                          const mold::ThermalSpec&) {
    ++built;
    CHECK(setting.heat_in.size() == 2);
    return eval::TemperatureSolver([&samples](const std::vector<thermal::Channel>& channels) {
      std::vector<double> t;
      for (const Vec3& p : samples.points) t.push_back(40 + 0.1 * p.x() + double(channels.size()));
      return eval::SolvedTemperatures{t, {}};
    });
  };
  const eval::Pipeline pipeline(scene, factory);
  CHECK(built == 1);
  const auto e = pipeline.evaluate(mold::load_layout(kBlockLayout, scene.spec()), true);
  // x = 31, 33, ..., 89 equally weighted: mean 60, population std 2 sqrt((30^2 - 1)/12).
  const double std_x = 2 * std::sqrt((30.0 * 30 - 1) / 12);
  REQUIRE(e.objectives.size() == 5);
  CHECK(e.objectives[0] == Approx(0.1 * std_x).epsilon(1e-12));
  CHECK(e.objectives[2] == Approx(40 + 6 + 3).epsilon(1e-12));
  CHECK(e.objectives[3] == Approx(40 + 8.9 + 3).epsilon(1e-12));
  CHECK(e.objectives[4] == Approx(eval::cooling_time(2.5, scene.spec().thermal.polymer, 51.9)).epsilon(1e-12));
  CHECK(e.objectives[1] > 0);  // cost
  bool timed = false;
  for (const auto& s : e.stages) timed = timed || s.name == "temperature_t2d";
  CHECK(timed);
}

TEST_CASE("temperature objectives: a layout solved before is not solved again, any other change is", "[eval][thermal]") {
  // A stand-in tier that counts its solves and reads every number of every channel.
  const mold::Scene scene(mold::load_mold_spec(kBlockSpec));
  int solves = 0;
  const eval::TemperatureSolverFactory factory = [&solves](const thermal::Setting&, const thermal::Samples& samples,
                                                           const mold::ThermalSpec&) {
    return eval::TemperatureSolver([&solves, &samples](const std::vector<thermal::Channel>& channels) {
      ++solves;
      double h = 0, k = 0;
      for (const thermal::Channel& c : channels)
        h += ++k * (c.axis.p0.sum() + 3 * c.axis.p1.sum() + 5 * c.radius + 7 * c.coolant + 11 * std::min(c.film, 1e3));
      std::vector<double> t;
      for (const Vec3& p : samples.points) t.push_back(40 + 1e-3 * h * p.x());
      return eval::SolvedTemperatures{t, {}};
    });
  };
  const eval::Pipeline pipeline(scene, factory);
  const mold::Layout a = mold::decode(scene, mold::load_layout(kBlockLayout, scene.spec()));
  REQUIRE(a.bores.size() >= 2);
  const auto first = pipeline.evaluate(a);
  CHECK(solves == 1);
  CHECK(pipeline.evaluate(a).objectives == first.objectives);
  CHECK(solves == 1);
  // Each change of a number the solve reads is a new solve: an end moved by one ulp, the
  // diameter, the bores' order (the last two with another result).
  mold::Layout moved = a, wider = a, swapped = a;
  moved.bores[0].flow_end.z() = std::nextafter(moved.bores[0].flow_end.z(), 1e9);
  wider.bores[0].diameter += 2;
  std::swap(swapped.bores[0], swapped.bores[1]);
  int expected = 1;
  for (const mold::Layout* l : {&moved, &wider, &swapped}) {
    const auto e = pipeline.evaluate(*l);
    CHECK(solves == ++expected);
    if (l != &moved) CHECK(e.objectives != first.objectives);
  }
  CHECK(pipeline.evaluate(a).objectives == first.objectives);
  CHECK(solves == expected);
}

TEST_CASE("temperature objectives: the default tier scores the reference block as FreeFem++ does", "[eval][thermal]") {
  // molds/thermal_block.yaml uses temperature_std and temperature_max; the layout is the case's.
  const mold::Scene scene(mold::load_mold_spec(kBlockSpec));
  const eval::Pipeline pipeline(scene);
  const auto e = pipeline.evaluate(mold::load_layout(kBlockLayout, scene.spec()));
  REQUIRE(e.feasible());
  // The FreeFem++ P2 reference at the same 720 samples (equal weights): population std and max.
  std::ifstream in(MTCS_TEST_DATA + "/thermal/patch_samples.csv");
  std::string line;
  std::getline(in, line);
  std::vector<double> t;
  while (std::getline(in, line)) t.push_back(std::stod(line.substr(line.rfind(',') + 1)));
  REQUIRE(t.size() == 720);
  double mean = 0, var = 0;
  for (double v : t) mean += v / 720;
  for (double v : t) var += (v - mean) * (v - mean) / 720;
  // The physical-proxy bars of shared/cases/thermal/README.md: |d std| <= 0.15 K; the max within
  // the tier's pointwise error (0.35 K, experiments/thermal/line_sinks.md).
  CHECK(e.objectives[0] == Approx(std::sqrt(var)).margin(0.15));
  CHECK(e.objectives[1] == Approx(*std::max_element(t.begin(), t.end())).margin(0.35));
}

TEST_CASE("patch cavity: bore_cavity is the clearance to the rectangle, not to its face", "[eval][thermal]") {
  const mold::Scene scene(mold::load_mold_spec(kBlockSpec));  // bore_cavity 3, bore_surface 3
  const eval::Pipeline pipeline(scene);
  auto cavity = [&](double y, double z) -> std::optional<eval::Violation> {
    for (const auto& v : pipeline.evaluate(mold::Genome{{{{{0, y, z}, {120, y, z}}, 6}}}).violations)
      if (v.kind == eval::ViolationKind::BoreCavity) return v;
    return std::nullopt;
  };
  // Under the patch, 2 mm of steel: violated by the exact shortfall.
  const auto under = cavity(40, 55);
  REQUIRE(under);
  CHECK(under->distance == Approx(2).margin(1e-12));
  CHECK(under->margin == 3);
  // Beside it (y = 8, the patch starts at 16): sqrt(8^2 + 5^2) - 3 = 6.43 mm from its edge.
  CHECK_FALSE(cavity(8, 55));
  // Just beside it (y = 14.5): the nearest point is the edge y = 16, z = 60, not the face:
  // sqrt(1.5^2 + 5^2) - 3 = 2.22 mm.
  const auto edge = cavity(14.5, 55);
  REQUIRE(edge);
  CHECK(edge->distance == Approx(std::sqrt(1.5 * 1.5 + 5.0 * 5.0) - 3).epsilon(1e-9));
}

TEST_CASE("issue 16: a layout that decodes to no bore scores the worst temperatures instead of ending the run",
          "[eval][thermal][issue16]") {
  // SMS-EMOA with defaults on molds/plate.yaml stopped on 5 of 11 seeds with "line sinks: no
  // channel and no isothermal face: no steady state": a genome whose circuit collapsed reached
  // the temperature stage with no bore.
  const mold::Scene scene(mold::load_mold_spec(MTCS_SOURCE_DIR + "/molds/plate.yaml"));
  const eval::Pipeline pipeline(scene);
  const eval::Evaluation none = pipeline.evaluate(mold::Layout{});
  const auto& use = scene.spec().objectives.use;
  bool any_temperature = false;
  for (std::size_t k = 0; k < use.size(); ++k) {
    if (!mold::is_temperature_objective(use[k])) continue;
    any_temperature = true;
    CHECK(std::isinf(none.objectives[k]));
    CHECK(none.objectives[k] > 0);
  }
  CHECK(any_temperature);
  // A layout that cools scores finite temperatures, below the empty one's.
  const auto layout = mold::decode(scene, mold::load_layout(MTCS_SOURCE_DIR + "/molds/plate.layout.yaml", scene.spec()));
  const eval::Evaluation some = pipeline.evaluate(layout);
  for (std::size_t k = 0; k < use.size(); ++k)
    if (mold::is_temperature_objective(use[k])) CHECK(std::isfinite(some.objectives[k]));
}
