// The thermal section of the mold spec, the face-patch cavity and the through-bores of the
// reference block: SI in the file, the thermal module's units in the spec, and every bad input
// an InputError at its line, column and field.

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>

#include <unistd.h>

#include "fuzz_mutate.h"
#include "../support/scratch_file.h"
#include "mtcs/io/input_error.h"
#include "mtcs/mold/decoder.h"
#include "mtcs/mold/layout_io.h"
#include "mtcs/mold/mold_spec.h"
#include "support/thrown_by.h"
#include "support/paths.h"

using namespace mtcs;
using geometry::Vec3;
namespace fs = std::filesystem;

namespace {

fs::path write(const std::string& name, const std::string& text) {
  return mtcs_test::write_scratch("thermal_spec_test", name, text);
}

const std::string kBlock = "block: {box: {min: [0, 0, 0], max: [120, 80, 60]}}\n";
const std::string kCavity = "cavity: {box: {min: [30, 16, 50], max: [90, 64, 55]}}\n";

mold::MoldSpec load(const std::string& text) { return mold::load_mold_spec(write("spec.yaml", text).string()); }

io::InputError error_of(const std::string& text) {
  return mtcs_test::thrown_by<io::InputError>([&] { load(text); }, text);
}

bool mentions(const io::InputError& e, const std::string& what) {
  return std::string(e.what()).find(what) != std::string::npos;
}

}  // namespace

TEST_CASE("thermal spec: defaults in the thermal module's units", "[mold][thermal]") {
  const auto t = load(kBlock).thermal;
  CHECK(t.conductivity == 0.03);
  CHECK(t.coolant_temperature == 40);
  CHECK_FALSE(t.coolant_film);
  CHECK_FALSE(t.flow_rate);
  CHECK(t.ambient_temperature == 25);
  CHECK(t.ambient_film == Approx(1e-5).epsilon(1e-15));
  CHECK(t.adiabatic_faces.empty());
  CHECK_FALSE(t.heat_flux);
  CHECK(t.polymer.melt_temperature == 230);
  CHECK(t.polymer.eject_temperature == 90);
  CHECK(t.polymer.diffusivity == Approx(0.2 / (1050 * 2000.0) * 1e6).epsilon(0.01));
  CHECK(t.tier == mold::ThermalTier::T2d);
  CHECK(t.elements_per_bore == 4);
  CHECK(t.objective_surface == mold::ObjectiveSurface::Heated);
}

TEST_CASE("thermal spec: cavity_void, ignore by default, plane on request", "[mold][thermal]") {
  CHECK_FALSE(load(kBlock).thermal.void_plane);
  CHECK_FALSE(load(kBlock + "thermal: {cavity_void: ignore}\n").thermal.void_plane);
  CHECK(load(kBlock + "thermal: {cavity_void: plane}\n").thermal.void_plane);
  const auto e = error_of(kBlock + "thermal:\n  cavity_void: mirror\n");
  CHECK(e.field() == "thermal.cavity_void");
  CHECK(e.line() == 3);
  CHECK(e.column() == 16);
}

TEST_CASE("thermal spec: cavity_void surface, its panels 8 mm unless void_panel says", "[mold][thermal]") {
  CHECK(load(kBlock).thermal.void_panel == 0);
  CHECK(load(kBlock + "thermal: {cavity_void: surface}\n").thermal.void_panel == 8);
  CHECK(load(kBlock + "thermal: {cavity_void: surface, void_panel: 12}\n").thermal.void_panel == 12);
  CHECK_FALSE(load(kBlock + "thermal: {cavity_void: surface}\n").thermal.void_plane);
  const auto alone = error_of(kBlock + "thermal:\n  void_panel: 12\n");
  CHECK(alone.field() == "thermal.void_panel");
  CHECK(alone.line() == 3);
  const auto tiny = error_of(kBlock + "thermal: {cavity_void: surface, void_panel: 0}\n");
  CHECK(tiny.field() == "thermal.void_panel");
  // A mesh cavity's void is a surface unless the spec says otherwise.
  CHECK(mold::load_mold_spec(MTCS_SOURCE_DIR + "/molds/gear.yaml").thermal.void_panel == 8);
  CHECK(mold::load_mold_spec(MTCS_SOURCE_DIR + "/docs/first-mold/part.yaml").thermal.void_panel == 8);
  CHECK(mold::load_mold_spec(MTCS_SOURCE_DIR + "/molds/thermal_block.yaml").thermal.void_panel == 0);
}

TEST_CASE("thermal spec: sample_spacing, the cavity's by default, coarser only", "[mold][thermal]") {
  const std::string cavity = "cavity: {box: {min: [20, 20, 30], max: [80, 60, 36]}, sample_spacing: 4}\n";
  CHECK_FALSE(load(kBlock + cavity).thermal.sample_spacing);
  CHECK(*load(kBlock + cavity + "thermal: {sample_spacing: 11}\n").thermal.sample_spacing == 11);
  CHECK(*load(kBlock + cavity + "thermal: {sample_spacing: 4}\n").thermal.sample_spacing == 4);
  // Finer than the cavity's: refused at the key, naming the cavity's spacing.
  const auto finer = error_of(kBlock + cavity + "thermal:\n  sample_spacing: 3.5\n");
  CHECK(finer.field() == "thermal.sample_spacing");
  CHECK(finer.line() == 4);
  CHECK(finer.column() == 19);
  CHECK(mentions(finer, "at least the cavity's sample_spacing (4 mm)"));
  for (const std::string bad : {"0", "-2", "abc", "[1, 2]"}) {
    const auto e = error_of(kBlock + cavity + "thermal:\n  sample_spacing: " + bad + "\n");
    CHECK(e.field() == "thermal.sample_spacing");
    CHECK(e.line() == 4);
  }
}

TEST_CASE("thermal spec: wall_images, 2 by default, 1 to 3", "[mold][thermal]") {
  CHECK(load(kBlock).thermal.wall_images == 2);
  CHECK(load(kBlock + "thermal: {wall_images: 1}\n").thermal.wall_images == 1);
  CHECK(load(kBlock + "thermal: {wall_images: 3}\n").thermal.wall_images == 3);
  for (const std::string bad : {"0", "4", "1.5", "two"}) {
    const auto e = error_of(kBlock + "thermal:\n  wall_images: " + bad + "\n");
    CHECK(e.field() == "thermal.wall_images");
    CHECK(e.line() == 3);
    CHECK(e.column() == 16);
  }
}

TEST_CASE("thermal spec: SI values are converted to mm, W and degrees C", "[mold][thermal]") {
  const auto t = load(kBlock +
                      "thermal:\n"
                      "  steel_conductivity: 45\n"
                      "  coolant: {temperature: 30, film: 5000}\n"
                      "  ambient: {temperature: 20, film: 8}\n"
                      "  adiabatic_faces: [-z, +y]\n"
                      "  heat_flux: 50000\n"
                      "  regions:\n"
                      "    - {box: {min: [0, 0, 59], max: [60, 80, 61]}, heat_flux: 80000}\n"
                      "  polymer: {melt_temperature: 250, eject_temperature: 100, diffusivity: 0.08}\n"
                      "  tier: fd\n"
                      "  elements_per_bore: 8\n"
                      "  cell_size: 1\n")
                     .thermal;
  CHECK(t.conductivity == Approx(0.045).epsilon(1e-15));
  CHECK(t.coolant_temperature == 30);
  CHECK(*t.coolant_film == Approx(5e-3).epsilon(1e-15));
  CHECK(t.ambient_film == Approx(8e-6).epsilon(1e-15));
  CHECK(t.adiabatic_faces == std::vector{mold::Face::NegZ, mold::Face::PosY});
  CHECK(*t.heat_flux == Approx(0.05).epsilon(1e-15));
  REQUIRE(t.regions.size() == 1);
  CHECK(t.regions[0].flux == Approx(0.08).epsilon(1e-15));
  CHECK(t.regions[0].box.max.z() == 61);
  CHECK(t.polymer.diffusivity == 0.08);
  CHECK(t.tier == mold::ThermalTier::Fd);
  CHECK(t.elements_per_bore == 8);
  CHECK(t.cell_size == 1);
  CHECK(*load(kBlock + "thermal: {coolant: {flow_rate: 8}}\n").thermal.flow_rate == 8);
  CHECK(load(kBlock + "thermal: {objective_surface: all}\n").thermal.objective_surface == mold::ObjectiveSurface::All);
  CHECK(load(kBlock + "thermal: {objective_surface: heated}\n").thermal.objective_surface == mold::ObjectiveSurface::Heated);
}

TEST_CASE("thermal spec: the temperature objectives and their scales", "[mold][thermal]") {
  const auto o = load(kBlock + kCavity +
                      "objectives:\n"
                      "  use: [temperature_std, temperature_mean, temperature_max, cycle_time, uniformity]\n"
                      "  scales: {temperature_std: 2, temperature_mean: 10, temperature_max: 20, cycle_time: 5}\n")
                     .objectives;
  using O = mold::Objective;
  CHECK(o.use == std::vector{O::TemperatureStd, O::TemperatureMean, O::TemperatureMax, O::CycleTime, O::Uniformity});
  CHECK(o.scale(O::TemperatureStd) == 2);
  CHECK(o.scale(O::TemperatureMean) == 10);
  CHECK(o.scale(O::TemperatureMax) == 20);
  CHECK(o.scale(O::CycleTime) == 5);
  CHECK(o.scale(O::Uniformity) == 5);
  for (const O x : o.use) CHECK(mold::objective_named(mold::to_string(x)) == x);
  CHECK(mold::is_temperature_objective(O::CycleTime));
  CHECK_FALSE(mold::is_temperature_objective(O::WorstCovered));
}

TEST_CASE("thermal spec: without objectives.use a part gets temperatures, a bare block its cost", "[mold][thermal]") {
  using O = mold::Objective;
  const auto part = load(kBlock + kCavity).objectives;
  CHECK(part.use == std::vector{O::TemperatureStd, O::TemperatureMax, O::Cost});
  CHECK(part.scale(O::TemperatureStd) == 1);
  CHECK(part.scale(O::TemperatureMax) == 10);
  CHECK(part.scale(O::Cost) == 1000);
  CHECK(load(kBlock + kCavity + "objectives: {scales: {cost: 50}}\n").objectives.use == part.use);
  CHECK(load(kBlock).objectives.use == std::vector{O::Cost});
  CHECK(load(kBlock + "objectives: {use: [cost]}\n").objectives.use == std::vector{O::Cost});
}

TEST_CASE("thermal spec: bad input names file, line, column and field", "[mold][thermal][errors]") {
  SECTION("a surface objective without a cavity") {
    const auto e = error_of(kBlock + "objectives:\n  use: [cost, temperature_max]\n");
    CHECK(e.field() == "objectives.use[1]");
    CHECK(e.line() == 3);
    CHECK(e.column() == 15);
    CHECK(mentions(e, "cavity"));
  }
  SECTION("film and flow rate") {
    const auto e = error_of(kBlock + "thermal:\n  coolant: {film: 5000, flow_rate: 8}\n");
    CHECK(e.field() == "thermal.coolant");
    CHECK(e.line() == 3);
    CHECK(e.column() == 12);
  }
  SECTION("a flow rate needs water") {
    const auto e = error_of(kBlock + "thermal:\n  coolant: {temperature: 150, flow_rate: 8}\n");
    CHECK(e.field() == "thermal.coolant.temperature");
    CHECK(e.line() == 3);
    CHECK(mentions(e, "water"));
  }
  SECTION("a negative film") {
    const auto e = error_of(kBlock + "thermal:\n  ambient:\n    film: -1\n");
    CHECK(e.field() == "thermal.ambient.film");
    CHECK(e.line() == 4);
    CHECK(e.column() == 11);
  }
  SECTION("unknown key") {
    const auto e = error_of(kBlock + "thermal:\n  polymer: {melt: 230}\n");
    CHECK(e.field() == "thermal.polymer.melt");
    CHECK(mentions(e, "unknown key"));
  }
  SECTION("tier 0 is an objective, not a tier") {
    const auto e = error_of(kBlock + "thermal: {tier: t0}\n");
    CHECK(e.field() == "thermal.tier");
    CHECK(mentions(e, "uniformity"));
  }
  SECTION("an unknown objective surface") {
    const auto e = error_of(kBlock + "thermal:\n  tier: t2\n  objective_surface: lower\n");
    CHECK(e.field() == "thermal.objective_surface");
    CHECK(e.line() == 4);
    CHECK(e.column() == 22);
    CHECK(mentions(e, "heated or all"));
  }
  SECTION("an unknown tier") { CHECK(error_of(kBlock + "thermal: {tier: t9}\n").field() == "thermal.tier"); }
  SECTION("eject above melt") {
    const auto e = error_of(kBlock + "thermal:\n  polymer: {melt_temperature: 200, eject_temperature: 210}\n");
    CHECK(e.field() == "thermal.polymer.eject_temperature");
    CHECK(e.line() == 3);
  }
  SECTION("coolant warmer than ejection") {
    const auto e = error_of(kBlock + "thermal:\n  coolant: {temperature: 95}\n");
    CHECK(e.field() == "thermal.coolant.temperature");
    CHECK(e.line() == 3);
  }
  SECTION("a region without a flux") {
    const auto e = error_of(kBlock + "thermal:\n  regions:\n    - {box: {min: [0, 0, 0], max: [1, 1, 1]}}\n");
    CHECK(e.field() == "thermal.regions[0]");
    CHECK(e.line() == 4);
  }
  SECTION("a flat region box") {
    const auto e = error_of(kBlock + "thermal:\n  regions:\n    - {box: {min: [0, 0, 60], max: [1, 1, 60]}, heat_flux: 1}\n");
    CHECK(e.field() == "thermal.regions[0].box.max");
  }
  SECTION("an unknown objective") {
    const auto e = error_of(kBlock + "objectives: {use: [temperature]}\n");
    CHECK(e.field() == "objectives.use[0]");
    CHECK(mentions(e, "cycle_time"));
  }
  SECTION("cost_per_part without the production it divides by") {
    const auto e = error_of(kBlock + kCavity + "objectives:\n  use: [cycle_time, cost_per_part]\n");
    CHECK(e.field() == "objectives.use[1]");
    CHECK(e.line() == 4);
    CHECK(mentions(e, "production"));
    CHECK(error_of(kBlock + "objectives:\n  production: {parts: 0, machine_rate: 50}\n").field() ==
          "objectives.production.parts");
    CHECK(error_of(kBlock + "objectives:\n  production: {parts: 1000}\n").field() == "objectives.production.machine_rate");
  }
  SECTION("a patch that leaves its face") {
    const auto e = error_of(kBlock + "cavity:\n  patch: {face: +z, min: [30, 16], max: [130, 64]}\n");
    CHECK(e.field() == "cavity.patch.max[0]");
    CHECK(e.line() == 3);
    CHECK(mentions(e, "along x"));
  }
  SECTION("a patch with max below min") {
    CHECK(error_of(kBlock + "cavity: {patch: {face: -y, min: [30, 50], max: [90, 40]}}\n").field() == "cavity.patch.max[1]");
  }
  SECTION("a patch and a box") {
    CHECK(error_of(kBlock + "cavity: {patch: {face: +z, min: [0, 0], max: [1, 1]}, box: {min: [1, 1, 1], max: [2, 2, 2]}}\n")
              .field() == "cavity");
  }
  SECTION("a patch on a face that is not one") {
    CHECK(error_of(kBlock + "cavity: {patch: {face: top, min: [0, 0], max: [1, 1]}}\n").field() == "cavity.patch.face");
  }
  SECTION("a patch with three coordinates") {
    CHECK(error_of(kBlock + "cavity: {patch: {face: +z, min: [0, 0, 60], max: [1, 1]}}\n").field() == "cavity.patch.min");
  }
}

TEST_CASE("thermal spec: a patch is a flat box on its face", "[mold][thermal]") {
  const auto spec = mold::load_mold_spec(MTCS_SOURCE_DIR + "/molds/thermal_block.yaml");
  REQUIRE(spec.cavity);
  CHECK(spec.cavity->is_patch());
  CHECK(*spec.cavity->patch_face == mold::Face::PosZ);
  CHECK(spec.cavity->box->min == Vec3(30, 16, 60));
  CHECK(spec.cavity->box->max == Vec3(90, 64, 60));
  CHECK(spec.cavity->bounds().max == Vec3(90, 64, 60));
  CHECK(spec.thermal.conductivity == Approx(0.03).epsilon(1e-15));
  CHECK(*spec.thermal.heat_flux == Approx(0.05).epsilon(1e-15));
  CHECK(spec.thermal.ambient_film == Approx(1e-5).epsilon(1e-15));
  CHECK(spec.thermal.coolant_temperature == 40);
  CHECK_FALSE(spec.thermal.coolant_film);
  // On the -y face the in-plane coordinates are x and z.
  const auto side = load(kBlock + "cavity: {patch: {face: -y, min: [10, 20], max: [50, 40]}}\n");
  CHECK(side.cavity->box->min == Vec3(10, 0, 20));
  CHECK(side.cavity->box->max == Vec3(50, 0, 40));
}

TEST_CASE("thermal spec: the reference layout decodes to the case's bores, straight through", "[mold][thermal]") {
  const mold::Scene scene(mold::load_mold_spec(MTCS_SOURCE_DIR + "/molds/thermal_block.yaml"));
  const auto genome = mold::load_layout(MTCS_SOURCE_DIR + "/molds/thermal_block.layout.yaml", scene.spec());
  const auto layout = mold::decode(scene, genome);
  // block3d_case.txt: B1 (y, z, D) = (20, 45, 10), B2 (40, 47, 8), B3 (61, 43, 10), x from 0 to 120.
  const double expected[3][3] = {{20, 45, 10}, {40, 47, 8}, {61, 43, 10}};
  REQUIRE(layout.bores.size() == 3);
  CHECK(layout.plugs == 0);
  CHECK(layout.ports.empty());
  for (std::size_t b = 0; b < 3; ++b) {
    const auto& bore = layout.bores[b];
    const Vec3 p0(0, expected[b][0], expected[b][1]), p1(120, expected[b][0], expected[b][1]);
    CHECK(bore.flow_start == p0);
    CHECK(bore.flow_end == p1);
    CHECK(bore.hole.p0 == p0);
    CHECK(bore.hole.p1 == p1);  // no drill point past an open end
    CHECK(bore.diameter == expected[b][2]);
    CHECK(bore.through);
    CHECK_FALSE(bore.plugged);
  }
}

TEST_CASE("thermal spec: the reader survives mutated thermal sections and patches", "[mold][thermal][fuzz]") {
  std::ifstream in(MTCS_SOURCE_DIR + "/molds/thermal_block.yaml");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  std::mt19937_64 rng(11);
  int loaded = 0, rejected = 0;
  for (int i = 0; i < 400; ++i) {
    const auto p = write("fuzz.yaml", mtcs_test::mutate(text, "0123456789,.-+:[]{}#\n xyzt_", rng, 4, 6));
    try {
      mold::load_mold_spec(p.string());
      ++loaded;
    } catch (const io::InputError& e) {
      REQUIRE(e.file() == p.string());
      ++rejected;
    }
  }
  CHECK(loaded > 0);
  CHECK(rejected > 0);
}

TEST_CASE("thermal spec: the cavity condition, flux by default, coupled with its film, temperature and cycle",
          "[mold][thermal]") {
  CHECK(load(kBlock).thermal.cavity_condition == mold::CavityCondition::Flux);
  const auto t = load(kBlock + "thermal:\n  cavity_condition: coupled\n  cycle: {fill: 0.5, pack: 2, open: 4, cooling: 9}\n").thermal;
  CHECK(t.cavity_condition == mold::CavityCondition::Coupled);
  CHECK(t.cycle.fill == 0.5);
  CHECK(t.cycle.pack == 2);
  CHECK(t.cycle.open == 4);
  CHECK(t.cycle.cooling == 9.0);
  CHECK_FALSE(t.part_film);
  // Either of the part's keys asks for the coupled condition; SI in the file.
  const auto given = load(kBlock + "thermal: {part_film: 150, part_temperature: 220}\n").thermal;
  CHECK(given.cavity_condition == mold::CavityCondition::Coupled);
  CHECK(*given.part_film == Approx(150e-6).epsilon(1e-12));
  CHECK(*given.part_temperature == 220);
  CHECK(mold::to_string(given.cavity_condition) == "coupled");
}

TEST_CASE("thermal spec: a cavity condition's keys that contradict it are errors at their line", "[mold][thermal]") {
  const auto flux = error_of(kBlock + "thermal:\n  cavity_condition: coupled\n  heat_flux: 30000\n");
  CHECK(flux.field() == "thermal.heat_flux");
  CHECK(flux.line() == 4);
  CHECK(mentions(flux, "part_film"));
  const auto film = error_of(kBlock + "thermal:\n  part_film: 120\n  cavity_condition: flux\n");
  CHECK(film.field() == "thermal.part_film");
  CHECK(film.line() == 3);
  const auto name = error_of(kBlock + "thermal:\n  cavity_condition: robin\n");
  CHECK(name.field() == "thermal.cavity_condition");
  CHECK(mentions(name, "coupled or flux"));
  const auto cold = error_of(kBlock + "thermal:\n  part_temperature: 30\n");
  CHECK(cold.field() == "thermal.part_temperature");
  const auto cycle = error_of(kBlock + "thermal:\n  cycle: {fill: 1, dwell: 3}\n");
  CHECK(cycle.field() == "thermal.cycle.dwell");
  const auto negative = error_of(kBlock + "thermal:\n  cycle: {open: -1}\n");
  CHECK(negative.field() == "thermal.cycle.open");
}

TEST_CASE("thermal spec: a coupled box cavity takes the void as a surface, the plane cut is refused", "[mold][thermal]") {
  const auto box = load(kBlock + kCavity + "thermal: {cavity_condition: coupled}\n").thermal;
  CHECK(box.void_panel == 8);
  CHECK_FALSE(box.void_plane);
  CHECK(load(kBlock + kCavity).thermal.void_panel == 0);  // the flux model: ignored, as before
  const auto plane = error_of(kBlock + kCavity + "thermal:\n  cavity_condition: coupled\n  cavity_void: plane\n");
  CHECK(plane.field() == "thermal.cavity_void");
  CHECK(plane.line() == 5);
  CHECK(mentions(plane, "cavity_void: surface"));
}

TEST_CASE("thermal spec: cavity.wall_thickness local, for a mesh cavity only", "[mold][thermal]") {
  const std::string mesh = MTCS_SOURCE_DIR + "/molds/meshes/cup.off";
  const std::string block = "block: {box: {min: [0, 0, 0], max: [220, 180, 120]}}\n";
  const mold::MoldSpec s = load(block + "cavity: {mesh: " + mesh + ", wall_thickness: local}\n");
  CHECK(s.cavity->local_thickness);
  CHECK_FALSE(load(block + "cavity: {mesh: " + mesh + ", wall_thickness: 3}\n").cavity->local_thickness);
  const io::InputError e = error_of(kBlock + "cavity: {box: {min: [30, 16, 50], max: [90, 64, 55]}, wall_thickness: local}\n");
  CHECK(e.field() == "cavity.wall_thickness");
  CHECK(mentions(e, "mesh cavity"));
  CHECK(error_of(kBlock + "cavity: {box: {min: [30, 16, 50], max: [90, 64, 55]}, wall_thickness: thick}\n").field() ==
        "cavity.wall_thickness");
}
