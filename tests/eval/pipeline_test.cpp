// The evaluation pipeline against numbers computed independently: closed-form gaps and wall
// distances, junctions, stages that a scene does not need, and a Monte Carlo check of the
// thermal proxy.

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include <unistd.h>
#include <random>
#include <thread>

#include "../support/scratch_file.h"
#include "mtcs/eval/pipeline.h"
#include "mtcs/opt/problem.h"
#include "mtcs/mold/decoder.h"
#include "mtcs/mold/layout_io.h"
#include "mtcs/mesh/bvh.h"
#include "mtcs/mesh/mesh_io.h"
#include "support/paths.h"
#include "support/bundled_variant.h"
#include "support/random_draws.h"

using namespace mtcs;
using geometry::Vec3;
namespace fs = std::filesystem;

namespace {

fs::path write(const std::string& name, const std::string& text) {
  return mtcs_test::write_scratch("pipeline_test", name, text);
}

// A 300 x 200 x 120 block with a plate cavity whose underside is at z = 105.
// The constraint tests need no thermal model (the default objectives are temperatures): cost
// alone, unless the test names its objectives.
std::string plate_spec(const std::string& extra = "", const std::string& objectives = "[cost]") {
  return "block: {box: {min: [0, 0, 0], max: [300, 200, 120]}}\n"
         "cavity: {box: {min: [50, 25, 105], max: [250, 175, 108]}, sample_spacing: 5}\n"
         "drilling: {diameters: [8], allowed_faces: [+y, -y]}\n"
         "circuits: {inlet_faces: [-y], outlet_faces: [+y]}\n"
         "objectives: {use: " + objectives + "}\n" + extra;
}

// One straight through-bore along y at (x, z).
mold::Circuit straight(double x, double z, double diameter = 8) { return {{{x, 0, z}, {x, 200, z}}, diameter}; }

const eval::Violation* find(const eval::Evaluation& e, eval::ViolationKind kind) {
  for (const auto& v : e.violations)
    if (v.kind == kind) return &v;
  return nullptr;
}

}  // namespace

TEST_CASE("pipeline: two parallel bores at a known gap violate the margin by the shortfall", "[eval]") {
  const mold::Scene scene(mold::load_mold_spec(write("gap.yaml", plate_spec("clearances: {bore_bore: 4}\n")).string()));
  const eval::Pipeline pipeline(scene);
  for (const double gap : {0.5, 2.0, 3.75}) {
    const auto e = pipeline.evaluate(mold::Genome{{straight(100, 80), straight(108 + gap, 80)}});
    const auto* v = find(e, eval::ViolationKind::BoreBore);
    REQUIRE(v);
    CHECK(v->distance == Approx(gap).margin(1e-12));
    CHECK(v->margin == 4);
    CHECK(v->amount == Approx((4 - gap) / 4).margin(1e-12));
    CHECK(v->elements == std::vector<std::string>{"c0.b0", "c1.b0"});
  }
  // At the margin or beyond: no violation.
  CHECK_FALSE(find(pipeline.evaluate(mold::Genome{{straight(100, 80), straight(112, 80)}}), eval::ViolationKind::BoreBore));
}

TEST_CASE("pipeline: a bore at a known depth under the plate has a known wall distance", "[eval]") {
  const mold::Scene scene(
      mold::load_mold_spec(write("wall.yaml", plate_spec("clearances: {bore_cavity: 20}\n")).string()));
  const eval::Pipeline pipeline(scene);
  // Axis 17 mm under the underside, radius 4: 13 mm of steel.
  const auto e = pipeline.evaluate(mold::Genome{{straight(150, 88)}});
  const auto* v = find(e, eval::ViolationKind::BoreCavity);
  REQUIRE(v);
  CHECK(v->distance == Approx(13).margin(1e-12));
  CHECK(v->margin == 20);
}

TEST_CASE("pipeline: designed junctions are not collisions, other crossings are", "[eval]") {
  const mold::Scene scene(mold::load_mold_spec(MTCS_SOURCE_DIR + "/molds/plate.yaml"));
  const eval::Pipeline pipeline(scene);
  const auto genome = mold::load_layout(MTCS_SOURCE_DIR + "/molds/plate.layout.yaml", scene.spec());
  const auto layout = mold::decode(scene, genome);
  CHECK(layout.junctions.size() == 6);
  CHECK(pipeline.evaluate(genome).feasible());
  // A new circuit whose second hole, along x at y = 100, cuts the right loop's legs.
  mold::Genome crossing = genome;
  crossing.circuits.push_back({{{150, 0, 88}, {150, 100, 88}, {300, 100, 88}}, 8});
  const auto e = pipeline.evaluate(crossing);
  int with_new = 0;
  for (const auto& v : e.violations)
    if (v.kind == eval::ViolationKind::BoreBore && (v.elements[0].rfind("c3.", 0) == 0 || v.elements[1].rfind("c3.", 0) == 0)) ++with_new;
  CHECK(with_new >= 2);
}

TEST_CASE("pipeline: a stage the scene does not need is not built and leaves no trace", "[eval]") {
  const mold::Scene plain(mold::load_mold_spec(
      write("plain.yaml", plate_spec()).string()));
  const eval::Pipeline pipeline(plain);
  const auto names = pipeline.stage_names();
  CHECK(std::find(names.begin(), names.end(), "thermal") == names.end());
  CHECK(std::find(names.begin(), names.end(), "bore_cavity_mesh") == names.end());
  CHECK(std::find(names.begin(), names.end(), "bore_keepout_cylinders") == names.end());
  CHECK(std::find(names.begin(), names.end(), "bore_keepout_meshes") == names.end());
  CHECK(pipeline.surface_samples() == 0);
  const auto e = pipeline.evaluate(mold::Genome{{straight(150, 88)}}, true);
  for (const auto& s : e.stages) {
    CHECK(s.name != "thermal");
    CHECK(s.name.find("mesh") == std::string::npos);
  }
  CHECK(e.objectives.size() == 1);
}

TEST_CASE("pipeline: built for the constraints alone, it has no objective stage and the same violations",
          "[eval]") {
  // molds/plate.yaml: temperature objectives (a line-sink model of seconds to build) and cost.
  const mold::Scene scene(mold::load_mold_spec(MTCS_SOURCE_DIR + "/molds/plate.yaml"));
  const eval::Pipeline full(scene);
  const eval::Pipeline clearances(scene, {}, eval::PipelineScope::constraints);
  const auto all = full.stage_names(), some = clearances.stage_names();
  for (const auto& name : some) CHECK(std::find(all.begin(), all.end(), name) != all.end());
  for (const char* objective : {"temperature_t2d", "cost"}) {
    CHECK(std::find(all.begin(), all.end(), objective) != all.end());
    CHECK(std::find(some.begin(), some.end(), objective) == some.end());
  }
  CHECK(some.size() + 2 == all.size());
  // A layout through the ejector pin at x = 60, and another under the cavity.
  const mold::Genome genome{{straight(60, 60), straight(150, 100)}};
  const mold::Layout layout = mold::decode(scene, genome);
  const auto a = full.constraints(layout), b = clearances.evaluate(layout);
  REQUIRE(a.violations.size() >= 2);
  REQUIRE(a.violations.size() == b.violations.size());
  for (std::size_t k = 0; k < a.violations.size(); ++k) {
    CHECK(a.violations[k].kind == b.violations[k].kind);
    CHECK(a.violations[k].distance == b.violations[k].distance);
  }
  CHECK(a.violation == b.violation);
  for (const double o : b.objectives) CHECK(o == 0);
}

TEST_CASE("pipeline: the thermal proxy agrees with a Monte Carlo estimate", "[eval]") {
  const mold::Scene scene(
      mold::load_mold_spec(write("thermal.yaml", plate_spec("", "[uniformity, worst_covered]")).string()));
  const eval::Pipeline pipeline(scene);
  const mold::Genome genome{{straight(100, 88), straight(200, 88)}};
  const auto e = pipeline.evaluate(genome);
  // Uniformity = sqrt(mean over the plate's surface of (e - 2D)^2), e = distance to the nearer
  // axis minus r; estimated with random points, area-weighted by picking faces by area.
  const geometry::Box plate{{50, 25, 105}, {250, 175, 108}};
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> u(0, 1);
  const Vec3 size = plate.size();
  const double areas[3] = {size.y() * size.z(), size.x() * size.z(), size.x() * size.y()};
  double sum = 0, worst = 0;
  const int n = 400000;
  for (int i = 0; i < n; ++i) {
    const double pick = u(rng) * (areas[0] + areas[1] + areas[2]);
    const int k = pick < areas[0] ? 0 : (pick < areas[0] + areas[1] ? 1 : 2);
    Vec3 p = plate.min + mtcs_test::draw_vec3(u, rng).cwiseProduct(size);
    p[k] = u(rng) < 0.5 ? plate.min[k] : plate.max[k];
    double best = 1e9;
    for (const double x : {100.0, 200.0}) best = std::min(best, Vec3(p.x() - x, 0, p.z() - 88).norm() - 4);
    sum += (best - 16) * (best - 16);
    worst = std::max(worst, best);
  }
  CHECK(e.objectives[0] == Approx(std::sqrt(sum / n)).epsilon(0.02));
  CHECK(e.objectives[1] == Approx(worst).epsilon(0.02));
}

TEST_CASE("pipeline: decoder routes axis-parallel holes, plugs side entries", "[eval][mold]") {
  const mold::Scene scene(mold::load_mold_spec(MTCS_SOURCE_DIR + "/molds/plate.yaml"));
  // A diagonal step is routed along the axes, longest leg first.
  const mold::Circuit c{{{70, 0, 88}, {110, 150, 88}, {110, 0, 88}}, 8};
  const auto pts = mold::routed_waypoints(scene, c);
  REQUIRE(pts.size() == 4);
  CHECK(pts[1] == Vec3(70, 150, 88));
  const auto layout = mold::decode(scene, mold::Genome{{c}});
  REQUIRE(layout.bores.size() == 3);
  CHECK(layout.plugs == 1);  // the cross hole, entered from -x
  CHECK(layout.bores[1].plugged);
  CHECK(layout.bores[1].entry_face == mold::Face::NegX);
  CHECK(layout.bores[1].hole.p0.x() == 0);
  CHECK(layout.bores[1].dead_end == Approx(70));  // from the plug at x = 0 to the junction at x = 70
  CHECK(layout.bores[0].dead_end == 0);
  // Through the drill point past the far junction: 0.5 D cot(59 deg).
  CHECK(layout.bores[1].hole.p1.x() == Approx(110 + 4 / std::tan(59 * M_PI / 180)));
  for (const auto& b : layout.bores) {
    const Vec3 d = (b.hole.p1 - b.hole.p0).cwiseAbs();
    CHECK((d.array() > 0).count() == 1);  // axis-parallel
  }
}

TEST_CASE("layout files round-trip", "[mold]") {
  const auto spec = mold::load_mold_spec(MTCS_SOURCE_DIR + "/molds/plate.yaml");
  const auto g = mold::load_layout(MTCS_SOURCE_DIR + "/molds/plate.layout.yaml", spec);
  const auto p = write("round.layout.yaml", "");
  mold::save_layout(p.string(), g);
  const auto h = mold::load_layout(p.string(), spec);
  REQUIRE(h.circuits.size() == g.circuits.size());
  for (std::size_t c = 0; c < g.circuits.size(); ++c) {
    CHECK(h.circuits[c].diameter == g.circuits[c].diameter);
    CHECK(h.circuits[c].waypoints == g.circuits[c].waypoints);
  }
}

TEST_CASE("penalty variants order layouts as documented", "[eval]") {
  auto spec = mold::load_mold_spec(MTCS_SOURCE_DIR + "/molds/plate.yaml");
  eval::Evaluation feasible, infeasible;
  feasible.objectives = {10, 10, 10};
  infeasible.objectives = {1, 1, 1};
  infeasible.violations.push_back({eval::ViolationKind::BoreBore, {"a", "b"}, 2, 4, 0.5, geometry::Vec3::Zero(), {}});
  infeasible.violation = 0.25;
  using mold::PenaltyVariant;
  // The order an optimiser ranks by: opt::Score with eval's scalar fitness as its value.
  auto score = [&](const eval::Evaluation& e) {
    return opt::Score{e.objectives, e.violation, e.feasible(), eval::scalar_fitness(e, spec, {}), {}};
  };
  spec.penalty.variant = PenaltyVariant::ConstrainedDomination;
  CHECK(score(feasible).value > score(infeasible).value);
  CHECK(opt::feasible_first(score(feasible), score(infeasible)));
  spec.penalty.variant = PenaltyVariant::StaticLinear;
  spec.penalty.weight = 1;
  // The objectives (1 each) over the mold's scales.
  REQUIRE(spec.objectives.use.size() == 3);
  double scaled = 0;
  for (const auto o : spec.objectives.use) scaled += 1 / spec.objectives.scale(o);
  CHECK(eval::scalar_fitness(infeasible, spec, {}) == Approx(scaled + 0.25));
  spec.penalty.variant = PenaltyVariant::StaticQuadratic;
  CHECK(eval::scalar_fitness(infeasible, spec, {}) == Approx(scaled + 0.0625));
  spec.penalty.variant = PenaltyVariant::Death;
  CHECK(std::isinf(eval::scalar_fitness(infeasible, spec, {})));
}

TEST_CASE("pipeline: a mesh cavity gives the exact solid-cylinder clearance and its place", "[eval]") {
  // The plate cavity as a closed mesh: the bores' distances are the closed forms of the box.
  const fs::path stl = write("plate_cavity.stl", "");
  mesh::write_stl(stl.string(), mesh::box_mesh({{50, 25, 105}, {250, 175, 108}}));
  const std::string spec = "block: {box: {min: [0, 0, 0], max: [300, 200, 120]}}\n"
                           "cavity: {mesh: " + stl.string() + ", sample_spacing: 5}\n"
                           "drilling: {diameters: [8], allowed_faces: [+y, -y]}\n"
                           "circuits: {inlet_faces: [-y], outlet_faces: [+y]}\n"
                           "clearances: {bore_cavity: 20}\n"
                           "objectives: {use: [cost]}\n";
  const mold::Scene scene(mold::load_mold_spec(write("mesh_cavity.yaml", spec).string()));
  const eval::Pipeline pipeline(scene);
  const auto names = pipeline.stage_names();
  REQUIRE(std::find(names.begin(), names.end(), "bore_cavity_mesh") != names.end());
  // Under the plate: 17 - 4 = 13 of steel, the place between the bore's top and the underside.
  auto e = pipeline.evaluate(mold::Genome{{straight(150, 88)}});
  auto* v = find(e, eval::ViolationKind::BoreCavity);
  REQUIRE(v);
  CHECK(v->distance == Approx(13).epsilon(1e-14));
  CHECK(v->where.x() == Approx(150).margin(1e-9));
  CHECK(v->where.y() >= 25 - 1e-9);
  CHECK(v->where.y() <= 175 + 1e-9);
  CHECK(v->where.z() == Approx(92 + 6.5).margin(1e-9));
  // Beside the plate's long edge x = 250, z = 105: axis 12 out and 12 down, 12 sqrt 2 - 4.
  e = pipeline.evaluate(mold::Genome{{straight(262, 93)}});
  v = find(e, eval::ViolationKind::BoreCavity);
  REQUIRE(v);
  CHECK(v->distance == Approx(12 * std::sqrt(2.0) - 4).epsilon(1e-14));
  // Through the plate: 0; far below it: no violation (the clearance bound ends the search).
  e = pipeline.evaluate(mold::Genome{{straight(150, 106.5)}});
  v = find(e, eval::ViolationKind::BoreCavity);
  REQUIRE(v);
  CHECK(v->distance == 0);
  CHECK_FALSE(find(pipeline.evaluate(mold::Genome{{straight(150, 40)}}), eval::ViolationKind::BoreCavity));
}

TEST_CASE("pipeline: constraints alone are evaluate's violations, objectives skipped", "[eval]") {
  // The reach move asks only for feasibility (Pipeline::constraints): the same violations, in
  // the same order, and the same CV as a full evaluation, on layouts with many violations.
  const std::string mold = GENERATE(std::string("plate_wall_distance"), std::string("gear"));
  const mold::MoldSpec spec = mold::load_mold_spec(mtcs_test::wall_distance_spec(mold));
  const mold::Scene scene(spec);
  const eval::Pipeline pipeline(scene);
  std::mt19937 gen(5);
  const geometry::Box& b = scene.block_bounds();
  std::uniform_real_distribution<double> u(0, 1);
  int violations = 0;
  for (int i = 0; i < 30; ++i) {
    mold::Genome g;
    for (int c = 0; c < 3; ++c) {
      mold::Circuit circuit{{}, spec.drilling.diameters.front()};
      Vec3 p(b.min.x() + u(gen) * b.size().x(), b.min.y(), b.min.z() + u(gen) * b.size().z());
      circuit.waypoints.push_back(p);
      p.y() = b.min.y() + u(gen) * b.size().y();
      circuit.waypoints.push_back(p);
      p.x() = b.min.x() + u(gen) * b.size().x();
      circuit.waypoints.push_back(p);
      p.y() = b.min.y();
      circuit.waypoints.push_back(p);
      g.circuits.push_back(circuit);
    }
    const mold::Layout layout = mold::decode(scene, g);
    const eval::Evaluation full = pipeline.evaluate(layout), alone = pipeline.constraints(layout);
    violations += int(full.violations.size());
    REQUIRE(alone.violations.size() == full.violations.size());
    for (std::size_t k = 0; k < full.violations.size(); ++k) {
      CHECK(alone.violations[k].kind == full.violations[k].kind);
      CHECK(alone.violations[k].elements == full.violations[k].elements);
      CHECK(alone.violations[k].distance == full.violations[k].distance);
      CHECK(alone.violations[k].amount == full.violations[k].amount);
    }
    CHECK(alone.violation == full.violation);
    CHECK(alone.feasible() == full.feasible());
    CHECK(alone.objectives == std::vector<double>(full.objectives.size(), 0.0));
  }
  CHECK(violations > 30);  // the layouts do violate: the comparison is not of empty lists
}

TEST_CASE("pipeline: the thermal stage's reused arrays carry nothing from one layout to the next", "[eval]") {
  // The stage keeps its per-slot arrays per thread and the first circuit overwrites them (no
  // fill): a layout scored after others (more circuits, other diameters, none at all) must equal
  // the same layout scored on a thread that has seen nothing (a new thread and pipeline per
  // layout: the arrays are per thread, not per pipeline).
  const mold::MoldSpec spec = mold::load_mold_spec(MTCS_SOURCE_DIR + "/molds/plate_wall_distance.yaml");
  const mold::Scene scene(spec);
  const eval::Pipeline warm(scene);
  const geometry::Box& b = scene.block_bounds();
  auto along_y = [&](double x, double z, double d) {
    return mold::Circuit{{{x, b.min.y(), z}, {x, b.max.y(), z}}, d};
  };
  const double d0 = spec.drilling.diameters.front(), d1 = spec.drilling.diameters.back();
  const double zc = (b.min.z() + b.max.z()) / 2, xc = (b.min.x() + b.max.x()) / 2;
  const std::vector<mold::Genome> layouts{
      mold::Genome{{along_y(xc - 40, zc, d0), along_y(xc, zc - 20, d1), along_y(xc + 40, zc, d0)}},
      mold::Genome{},  // no bores: every sample at the block's diagonal
      mold::Genome{{along_y(xc + 10, zc + 5, d1)}},
      mold::Genome{{along_y(xc - 60, zc - 10, d0), along_y(xc + 60, zc + 10, d0)}},
      mold::Genome{},
  };
  for (const auto& g : layouts) {
    std::vector<double> cold;
    std::thread([&] { cold = eval::Pipeline(scene).evaluate(g).objectives; }).join();
    CHECK(warm.evaluate(g).objectives == cold);
  }
}

TEST_CASE("pipeline: the thermal stage's rows of a layout stay whole when its circuit cache starts over",
          "[eval]") {
  // The stage keeps two generations of 128 circuits per thread, their rows in a ring of 320; a
  // circuit found in the old generation gets a fresh row. Below: a layout that revives old
  // circuits, hits young ones written ~100 rows before and adds new ones while the young
  // generation turns over; then, 90 rows later (row 0 written over), a layout of revived circuits
  // whose first rows were 0-3. Each layout scored warm must equal it scored on a thread and
  // pipeline that saw nothing.
  const mold::MoldSpec spec = mold::load_mold_spec(MTCS_SOURCE_DIR + "/molds/plate_wall_distance.yaml");
  const mold::Scene scene(spec);
  const geometry::Box& b = scene.block_bounds();
  const double d = spec.drilling.diameters.front();
  auto along_y = [&](double x, double z) { return mold::Circuit{{{x, b.min.y(), z}, {x, b.max.y(), z}}, d}; };
  auto cold = [&](const mold::Genome& g) {
    std::vector<double> out;
    std::thread([&] { out = eval::Pipeline(scene).evaluate(g).objectives; }).join();
    return out;
  };
  auto singles = [&](int n, double z) {
    mold::Genome last;
    for (int i = 0; i < n; ++i) last.circuits.push_back(along_y(20 + 0.5 * i, z));
    return last;
  };
  const eval::Pipeline warm(scene);
  std::thread([&] {
    const mold::Genome first{{along_y(30, 20), along_y(60, 25), along_y(90, 30), along_y(120, 35)}};
    warm.evaluate(first);  // rows 0-3
    const mold::Genome a = singles(124, 60), b = singles(100, 70), c = singles(90, 90);
    for (const auto& circuit : a.circuits) warm.evaluate(mold::Genome{{circuit}});  // the young one full
    for (const auto& circuit : b.circuits) warm.evaluate(mold::Genome{{circuit}});  // the next
    mold::Genome big = first;                                                       // revived
    big.circuits.insert(big.circuits.end(), b.circuits.begin(), b.circuits.begin() + 30);  // young
    big.circuits.insert(big.circuits.end(), a.circuits.begin(), a.circuits.begin() + 10);  // revived
    for (int i = 0; i < 20; ++i) big.circuits.push_back(along_y(40 + 0.5 * i, 80));      // new
    CHECK(warm.evaluate(big).objectives == cold(big));
    for (const auto& circuit : c.circuits) warm.evaluate(mold::Genome{{circuit}});
    CHECK(warm.evaluate(first).objectives == cold(first));
  }).join();
}
