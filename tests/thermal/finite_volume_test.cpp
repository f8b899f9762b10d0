// T3, the finite-volume reference, against independent references: the FreeFem++ P2 solution of
// the reference block (shared/cases/thermal), closed-form shape factors, and physical limits.
#include "mtcs/thermal/finite_volume.h"

#include <algorithm>
#include <catch2/catch.hpp>

#include "rank_statistics.h"
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>

#include "mtcs/mesh/triangle_mesh.h"
#include "support/paths.h"

using namespace mtcs::thermal;

namespace {

// The reference block of shared/cases/thermal/block3d_case.txt, offset by `shift`.
Model block_case(const Vec3& shift = Vec3::Zero()) {
  Model m;
  Setting& s = m.setting;
  s.block = {Vec3(0, 0, 0) + shift, Vec3(120, 80, 60) + shift};
  s.conductivity = 0.03;
  for (auto& f : s.faces) f = {1e-5, 25};
  const double q = 0.05;
  const Vec3 a = Vec3(30, 16, 60) + shift, b = Vec3(90, 16, 60) + shift, c = Vec3(90, 64, 60) + shift,
             d = Vec3(30, 64, 60) + shift;
  // Counter-clockwise seen from +z (the melt's side).
  s.heat_in = {{a, b, c, q}, {a, c, d, q}};
  const auto bore = [&](double y, double z, double diameter) {
    Channel ch;
    ch.axis = {Vec3(0, y, z) + shift, Vec3(120, y, z) + shift};
    ch.radius = diameter / 2;
    ch.coolant = 40;
    return ch;
  };
  m.channels = {bore(20, 45, 10), bore(40, 47, 8), bore(61, 43, 10)};
  return m;
}

struct Reference {
  Samples samples;
  std::vector<double> temperature;
};

Reference patch_samples(const Vec3& shift = Vec3::Zero()) {
  std::ifstream in(MTCS_TEST_DATA + "/thermal/patch_samples.csv");
  REQUIRE(in);
  Reference r;
  std::string line;
  std::getline(in, line);  // x,y,z,T
  while (std::getline(in, line)) {
    double x, y, z, t;
    char comma;
    std::istringstream row(line);
    row >> x >> comma >> y >> comma >> z >> comma >> t;
    r.samples.points.push_back(Vec3(x, y, z) + shift);
    r.samples.weights.push_back(1.0);
    r.temperature.push_back(t);
  }
  REQUIRE(r.samples.size() == 720);
  return r;
}

struct Errors {
  double rms = 0, max = 0, mean = 0, std = 0;  // mean and std: differences of the statistics
  double spearman = 0;                         // rank correlation with the reference
};



Errors compare(const std::vector<double>& t, const Reference& ref) {
  Errors e;
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double d = t[i] - ref.temperature[i];
    e.rms += d * d;
    e.max = std::max(e.max, std::abs(d));
  }
  e.rms = std::sqrt(e.rms / double(t.size()));
  const Summary a = summarize(t, ref.samples), b = summarize(ref.temperature, ref.samples);
  e.mean = a.mean - b.mean;
  e.std = a.std - b.std;
  e.spearman = mtcs_test::spearman(t, ref.temperature);
  return e;
}

double balance_error(const FvResult& r) {
  return std::abs(r.heat_in - r.heat_to_channels - r.heat_to_faces) / r.heat_in;
}

bool all_finite(const FvResult& r) {
  for (double t : r.temperature)
    if (!std::isfinite(t)) return false;
  return std::isfinite(r.heat_to_channels) && std::isfinite(r.heat_to_faces);
}

// Without heat_in: what the channels give (negative: heat leaves them) the faces take.
double balance_error_to_faces(const FvResult& r) {
  return std::abs(r.heat_to_channels + r.heat_to_faces) / std::abs(r.heat_to_faces);
}

// The reference block solved at the patch samples, once per cell size for the whole run.
const FvResult& block_solution(double cell) {
  static std::map<double, FvResult> solved;
  auto it = solved.find(cell);
  if (it == solved.end())
    it = solved.emplace(cell, solve_finite_volume(block_case(), patch_samples().samples, {cell})).first;
  return it->second;
}

}  // namespace

TEST_CASE("finite volume: the reference block at 2 mm is near FreeFem's P2 solution", "[fv]") {
  const Reference ref = patch_samples();
  const FvResult& r = block_solution(2.0);
  const Errors e = compare(r.temperature, ref);
  INFO("rms " << e.rms << " max " << e.max << " dmean " << e.mean << " dstd " << e.std << " s " << r.seconds
              << " it " << r.iterations);
  CHECK(r.converged);
  CHECK(r.heat_in == Approx(144.0).epsilon(1e-12));
  CHECK(balance_error(r) < 1e-6);
  CHECK(r.heat_to_channels == Approx(137.82).margin(0.3));
  CHECK(r.heat_to_faces == Approx(6.18).margin(0.3));
  CHECK(e.rms < 0.4);
}

TEST_CASE("finite volume: the reference block at 1 mm meets the reference-tier bars", "[fv]") {
  const Reference ref = patch_samples();
  const FvResult& r = block_solution(1.0);
  const Errors e = compare(r.temperature, ref);
  INFO("rms " << e.rms << " max " << e.max << " dmean " << e.mean << " dstd " << e.std << " rho "
              << e.spearman << " s " << r.seconds);
  // The bars of shared/cases/thermal/README.md for a reference tier.
  CHECK(e.rms <= 0.1);
  CHECK(std::abs(e.mean) <= 0.1);
  CHECK(std::abs(e.std) <= 0.05);
  CHECK(e.spearman >= 0.9995);
  CHECK(balance_error(r) < 1e-6);
  // FreeFem's heat balance: 137.82 W to the bores, 6.18 W convected (to 0.01 W).
  CHECK(r.heat_to_channels == Approx(137.82).margin(0.02));
  CHECK(r.heat_to_faces == Approx(6.18).margin(0.02));
}

TEST_CASE("finite volume: the error against FreeFem falls as h^2", "[fv]") {
  // Least-squares slope of log RMS over log h: single grids wander with how the bore walls fall
  // between the centres, the trend does not.
  const Reference ref = patch_samples();
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const std::vector<double> cells{4.0, 3.0, 2.0, 1.5, 1.0};
  for (double cell : cells) {
    const FvResult& r = block_solution(cell);
    const double x = std::log(cell), y = std::log(compare(r.temperature, ref).rms);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  const double n = double(cells.size());
  const double order = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  INFO("observed order " << order);
  CHECK(order > 1.6);
  CHECK(order < 3.2);
}

namespace {

// One hole of diameter D with its axis at depth z under an isothermal face (a very large film),
// in a slab one cell thick along the axis with adiabatic ends, sides and bottom at W = 20 z.
// k = 1 and a unit temperature difference: the heat per unit length is the shape factor.
double single_hole_shape_factor(double diameter, double depth, double cell) {
  const double half_width = 20 * depth;
  Model m;
  Setting& s = m.setting;
  s.block = {Vec3(0, -half_width, -half_width), Vec3(cell, half_width, depth)};
  s.conductivity = 1;
  for (auto& f : s.faces) f = {0, 0};
  s.faces[int(BlockFace::PosZ)] = {1e9, 0};
  Channel hole;
  hole.axis = {Vec3(-1, 0, 0), Vec3(cell + 1, 0, 0)};
  hole.radius = diameter / 2;
  hole.coolant = 1;
  m.channels = {hole};
  const FvResult r = solve_finite_volume(m, {}, {cell, 1e-12});
  CHECK(balance_error_to_faces(r) < 1e-6);
  return r.heat_to_channels / -cell;
}

}  // namespace

TEST_CASE("finite volume: one hole under an isothermal face has S = 2 pi / acosh(2z/D)", "[fv]") {
  // closed_form_2d.csv rows hole_iso_a1 and hole_iso_a3, at 1 mm. The plate of half-width 20 z
  // stands for the semi-infinite medium at a cost of -0.2 % (FreeFem study of the same file).
  struct Row {
    double diameter, depth, expected;
  };
  for (const Row& row : {Row{10.0, 7.5, 6.5285026}, Row{8.0, 13.0, 3.4013797}}) {
    const double s = single_hole_shape_factor(row.diameter, row.depth, 1.0);
    INFO("D " << row.diameter << " z " << row.depth << " S " << s << " expected " << row.expected);
    CHECK(std::abs(s / row.expected - 1) < 0.006);
  }
}

TEST_CASE("finite volume: the single-hole shape factor converges on refinement", "[fv]") {
  const double expected = 6.5285026 * (1 - 0.002);  // hole_iso_a1, less the plate's -0.2 %
  const double coarse = single_hole_shape_factor(10, 7.5, 1.0), fine = single_hole_shape_factor(10, 7.5, 0.5);
  INFO("S(1 mm) " << coarse << " S(0.5 mm) " << fine << " plate value " << expected);
  CHECK(std::abs(fine - expected) < 0.7 * std::abs(coarse - expected));
}

namespace {

// A row of holes at pitch w and depth z under the top face, bottom adiabatic at z + 3w, as the
// half cell between a hole's mid-plane and the mid-pitch plane (both adiabatic by symmetry),
// one cell thick along the holes. With `flux` the top takes q and the holes are at 0 degrees;
// otherwise the top is isothermal at 0 (a very large film) and the holes at 1.
FvResult row_of_holes(double diameter, double depth, double pitch, double cell, bool flux) {
  const double top = depth + 3 * pitch, half = pitch / 2;
  Model m;
  m.setting.block = {Vec3(0, 0, 0), Vec3(cell, half, top)};
  m.setting.conductivity = flux ? 0.03 : 1;
  for (auto& f : m.setting.faces) f = {0, 0};
  if (flux) {
    const Vec3 a(0, 0, top), b(cell, 0, top), c(cell, half, top), d(0, half, top);
    m.setting.heat_in = {{a, b, c, 0.05}, {a, c, d, 0.05}};
  } else {
    m.setting.faces[int(BlockFace::PosZ)] = {1e9, 0};
  }
  Channel hole;
  hole.axis = {Vec3(-1, 0, top - depth), Vec3(cell + 1, 0, top - depth)};
  hole.radius = diameter / 2;
  hole.coolant = flux ? 0 : 1;
  m.channels = {hole};
  Samples ends;  // above the hole and at mid-pitch
  ends.points = {Vec3(cell / 2, 0, top), Vec3(cell / 2, half, top)};
  ends.weights = {1, 1};
  return solve_finite_volume(m, ends, {cell, 1e-12});
}

}  // namespace

TEST_CASE("finite volume: a row of holes matches FreeFem's periodic cells", "[fv]") {
  // closed_form_2d.csv, the rows judged against FreeFem (the line-sink formulas are off there):
  // the face's spread under a flux, and the shape factor per hole under an isothermal face.
  struct Row {
    const char* name;
    double diameter, depth, pitch, fem;
    bool flux;
  };
  const Row rows[] = {{"row_flux_b0", 10, 15, 30, 2.1311632, true},
                      {"row_flux_b1", 8, 14, 40, 5.6348558, true},
                      {"row_flux_b4", 10, 12, 20, 1.1117348, true},
                      {"row_iso_b0", 10, 15, 30, 2.2156942, false},
                      {"row_iso_b4", 10, 12, 20, 2.2574696, false}};
  for (const Row& row : rows) {
    const double cell = 0.5;
    const FvResult r = row_of_holes(row.diameter, row.depth, row.pitch, cell, row.flux);
    const double value = row.flux ? r.temperature[1] - r.temperature[0] : -2 * r.heat_to_channels / cell;
    INFO(row.name << ": FV " << value << ", FreeFem " << row.fem);
    CHECK(value == Approx(row.fem).epsilon(4e-3));
  }
}

TEST_CASE("finite volume: the row-of-holes error falls as h^2", "[fv]") {
  // row_flux_b4 and row_iso_b4 of closed_form_2d.csv (FreeFem P2, adapted) at 0.5 and 0.25 mm.
  for (bool flux : {true, false}) {
    const double fem = flux ? 1.1117348 : 2.2574696;
    double error[2];
    for (int level = 0; level < 2; ++level) {
      const double cell = level == 0 ? 0.5 : 0.25;
      const FvResult r = row_of_holes(10, 12, 20, cell, flux);
      const double value = flux ? r.temperature[1] - r.temperature[0] : -2 * r.heat_to_channels / cell;
      error[level] = std::abs(value - fem);
    }
    INFO((flux ? "spread" : "shape factor")
         << ": error " << error[0] << " at 0.5 mm, " << error[1] << " at 0.25 mm");
    CHECK(error[0] / error[1] > 3);  // observed order > 1.58
  }
}

// Not in the stiff set above: that one also runs under the sanitizers, and this one is heavier.
TEST_CASE("finite volume: cell centres on a bore wall and a hair off it", "[fv]") {
  const Reference ref = patch_samples();
  // At 2 mm four cell centres lie exactly on B1's wall; moved off by 1e-12 ... 1e-6 mm they
  // become steel with a conductance to the wall up to 1e9 times the others'. The field must
  // not notice (it did, by 10 K, while those rows dominated the CG tolerance). Measured: 8e-7 K.
  const FvResult& on = block_solution(2.0);
  for (double shift : {1e-12, 1e-9, -1e-9, 1e-6}) {
    Model m = block_case();
    m.channels[0].axis.p0.z() += shift;
    m.channels[0].axis.p1.z() += shift;
    const FvResult off = solve_finite_volume(m, ref.samples, {2.0});
    REQUIRE(all_finite(off));
    CHECK(balance_error(off) < 1e-6);
    double worst = 0;
    for (std::size_t i = 0; i < off.temperature.size(); ++i)
      worst = std::max(worst, std::abs(off.temperature[i] - on.temperature[i]));
    INFO("shift " << shift << ": max difference " << worst);
    CHECK(worst < 1e-5);  // the geometry moved by at most 1e-6 mm
  }
}

TEST_CASE("finite volume: a flat bore wall with a film is exact in one dimension", "[fv]") {
  // A bore of radius 1e6 mm: its wall crosses the block as the plane z = 3.3 (sagitta 5e-5 mm),
  // between grid planes. Adiabatic sides, the flux q on the top face: the temperature is linear,
  // T(top) = coolant + q / film + q (20 - 3.3) / k, which the scheme reproduces.
  const double q = 0.05, k = 0.03, wall = 3.3, radius = 1e6;
  for (double film : {1e-3, std::numeric_limits<double>::infinity()}) {
    Model m;
    m.setting.block = {Vec3(0, 0, 0), Vec3(10, 10, 20)};
    m.setting.conductivity = k;
    for (auto& f : m.setting.faces) f = {0, 25};
    const Vec3 a(0, 0, 20), b(10, 0, 20), c(10, 10, 20), d(0, 10, 20);
    m.setting.heat_in = {{a, b, c, q}, {a, c, d, q}};
    Channel bore;
    bore.axis = {Vec3(-1, 5, wall - radius), Vec3(11, 5, wall - radius)};
    bore.radius = radius;
    bore.film = film;
    m.channels = {bore};
    Samples top;
    top.points = {Vec3(5, 5, 20), Vec3(0.2, 9.7, 20)};
    top.weights = {1, 1};
    const FvResult r = solve_finite_volume(m, top, {1.0, 1e-12});
    const double expected = 40 + (std::isinf(film) ? 0.0 : q / film) + q * (20 - wall) / k;
    INFO("film " << film);
    CHECK(r.temperature[0] == Approx(expected).margin(1e-3));
    CHECK(r.temperature[1] == Approx(expected).margin(1e-3));
    CHECK(r.heat_to_channels == Approx(q * 100).epsilon(1e-8));
  }
}

TEST_CASE("finite volume: stiff and extreme inputs stay finite and meet their limits", "[fv][stiff]") {
  const Reference ref = patch_samples();

  const FvOptions options{4.0};
  const FvResult base = solve_finite_volume(block_case(), ref.samples, options);

  SECTION("a bore 1e-3 mm under the heated face") {
    Model m = block_case();
    m.channels[1].axis.p0.z() = m.channels[1].axis.p1.z() = 60 - 4 - 1e-3;
    for (double cell : {4.0, 2.0}) {
      const FvResult r = solve_finite_volume(m, ref.samples, {cell});
      REQUIRE(all_finite(r));
      CHECK(balance_error(r) < 1e-6);
      // The face above the bore is held near the coolant; nothing anywhere falls below it.
      const Summary s = summarize(r.temperature, ref.samples);
      CHECK(*std::min_element(r.temperature.begin(), r.temperature.end()) >= 40);
      CHECK(r.field.temperature_at(Vec3(60, 40, 60)) < 41);
      CHECK(s.max < base.temperature[0] + 20);
    }
  }
  SECTION("points far away or not finite have no temperature") {
    for (const Vec3& p : {Vec3(1e300, 0, 0), Vec3(-1e9, 40, 30), Vec3(60, 40, 75), Vec3(NAN, 1, 1)})
      CHECK(std::isnan(base.field.temperature_at(p)));
    CHECK(std::isfinite(base.field.temperature_at(Vec3(60, 40, 61))));  // within a cell: extrapolated
  }
  SECTION("film -> infinity is the Dirichlet limit") {
    Model m = block_case();
    for (auto& ch : m.channels) ch.film = 1e9;
    const FvResult r = solve_finite_volume(m, ref.samples, options);
    REQUIRE(all_finite(r));
    for (std::size_t i = 0; i < r.temperature.size(); ++i)
      CHECK(r.temperature[i] == Approx(base.temperature[i]).margin(1e-6));
  }
  SECTION("film -> 0 leaves an adiabatic block that only the faces cool") {
    Model m = block_case();
    for (auto& ch : m.channels) ch.film = 1e-15;
    const FvResult r = solve_finite_volume(m, ref.samples, options);
    REQUIRE(all_finite(r));
    CHECK(balance_error(r) < 1e-6);
    CHECK(std::abs(r.heat_to_channels) < 1e-6 * r.heat_in);
    // Biot number h L / k = 0.04: the steel is nearly isothermal at the temperature where the
    // open faces (all but the patch and the bore mouths) convect 144 W.
    const double open = 2 * (120 * 80 + 120 * 60 + 80 * 60) - 60 * 48 - 2 * M_PI * (25 + 16 + 25);
    const double lumped = 25 + 144 / (1e-5 * open);
    const Summary s = summarize(r.temperature, ref.samples);
    CHECK(s.mean > lumped);  // the heated patch is the hottest place
    CHECK(s.mean < lumped + 0.1 * (lumped - 25));
  }
  SECTION("conductivity x 1e3 scales the rise above the coolant by 1e-3") {
    Model m = block_case();
    for (auto& f : m.setting.faces) f.film = 0;  // only the bores cool: T - 40 goes as 1 / k
    const FvResult slow = solve_finite_volume(m, ref.samples, {4.0, 1e-13});
    m.setting.conductivity *= 1e3;
    const FvResult fast = solve_finite_volume(m, ref.samples, {4.0, 1e-13});
    REQUIRE(all_finite(fast));
    for (std::size_t i = 0; i < slow.temperature.size(); ++i)
      CHECK((fast.temperature[i] - 40) == Approx(1e-3 * (slow.temperature[i] - 40)).epsilon(1e-6));
  }
  SECTION("coordinates offset by 1e4 mm give the same field") {
    const Vec3 shift(1e4, -1e4, 1e4);
    const Reference far = patch_samples(shift);
    const FvResult r = solve_finite_volume(block_case(shift), far.samples, options);
    REQUIRE(all_finite(r));
    for (std::size_t i = 0; i < r.temperature.size(); ++i)
      CHECK(r.temperature[i] == Approx(base.temperature[i]).margin(1e-6));
    CHECK(r.heat_to_channels == Approx(base.heat_to_channels).epsilon(1e-9));
  }
}

namespace {

// The reference block grown 10 mm upwards, the growth a cavity void over the whole top: the
// same steel as block_case() with an adiabatic top, heated through the cavity's floor.
Model block_under_a_cavity(bool as_mesh) {
  Model m = block_case();
  m.setting.block.max.z() = 70;
  const Box cavity{Vec3(-1, -1, 60), Vec3(121, 81, 71)};
  if (!as_mesh) {
    m.setting.cavity_box = cavity;
    return m;
  }
  auto mesh = std::make_shared<mtcs::mesh::TriangleMesh>();
  for (int corner = 0; corner < 8; ++corner)
    mesh->vertices.push_back(Vec3(corner & 1 ? cavity.max.x() : cavity.min.x(),
                                  corner & 2 ? cavity.max.y() : cavity.min.y(),
                                  corner & 4 ? cavity.max.z() : cavity.min.z()));
  mesh->triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                     {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  REQUIRE(mtcs::mesh::closed_mesh_problem(*mesh).empty());
  m.setting.cavity_mesh = mesh;
  return m;
}

}  // namespace

TEST_CASE("finite volume: heat through a cavity void's wall matches the same heat on a block face", "[fv]") {
  const Reference ref = patch_samples();
  Model on_face = block_case();
  on_face.setting.faces[int(BlockFace::PosZ)].film = 0;  // the cavity's floor does not convect
  const FvResult face = solve_finite_volume(on_face, ref.samples, {2.0});
  for (bool as_mesh : {false, true}) {
    const FvResult wall = solve_finite_volume(block_under_a_cavity(as_mesh), ref.samples, {2.0});
    CHECK(wall.steel_cells == face.steel_cells);
    CHECK(wall.heat_in == Approx(144).epsilon(1e-12));
    CHECK(balance_error(wall) < 1e-6);
    double rms = 0;
    for (std::size_t i = 0; i < ref.samples.size(); ++i)
      rms += std::pow(wall.temperature[i] - face.temperature[i], 2);
    rms = std::sqrt(rms / double(ref.samples.size()));
    INFO("mesh " << as_mesh << " rms difference " << rms);
    CHECK(rms < 0.05);
  }
}

TEST_CASE("finite volume: models and options it cannot solve are rejected", "[fv]") {
  const Samples none;
  CHECK_THROWS_AS(solve_finite_volume(block_case(), none, {0.0}), std::invalid_argument);
  CHECK_THROWS_AS(solve_finite_volume(block_case(), none, {NAN}), std::invalid_argument);
  Model m = block_case();
  m.setting.conductivity = 0;
  CHECK_THROWS_AS(solve_finite_volume(m, none, {4.0}), std::invalid_argument);
  m = block_case();
  m.setting.block.max.x() = m.setting.block.min.x();
  CHECK_THROWS_AS(solve_finite_volume(m, none, {4.0}), std::invalid_argument);
  m = block_case();
  m.channels[0].film = 0;
  CHECK_THROWS_AS(solve_finite_volume(m, none, {4.0}), std::invalid_argument);
  m = block_case();
  m.setting.faces[2].film = -1;
  CHECK_THROWS_AS(solve_finite_volume(m, none, {4.0}), std::invalid_argument);
  m = block_case();
  m.setting.heat_in[0].flux = NAN;
  CHECK_THROWS_AS(solve_finite_volume(m, none, {4.0}), std::invalid_argument);
}

TEST_CASE("finite volume: a solve cut short says so", "[fv]") {
  FvOptions options{4.0};
  options.max_iterations = 3;
  const FvResult r = solve_finite_volume(block_case(), {}, options);
  CHECK_FALSE(r.converged);
  CHECK(r.iterations == 3);
  CHECK(r.residual > options.tolerance);
}
