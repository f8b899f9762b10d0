// The line-sink tiers against independent references: the 2-D closed forms of
// shared/cases/thermal/closed_form_2d.csv, the FreeFem++ P2 solution of the block case at its
// 720 patch samples, and the limits of stiff and extreme inputs.
#include <catch2/catch.hpp>

#include "rank_statistics.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cmath>
#include <fstream>
#include <limits>
#include <numbers>
#include <optional>
#include <random>
#include <sstream>
#include <string>

#include "mtcs/thermal/line_sinks.h"
#include "support/paths.h"

using namespace mtcs::thermal;
using mtcs::geometry::Segment;

namespace {

// The block case of block3d_case.txt, in mm / W / degC.
Setting block_setting() {
  Setting s;
  s.block = {Vec3(0, 0, 0), Vec3(120, 80, 60)};
  s.conductivity = 0.03;
  for (auto& f : s.faces) f = {1e-5, 25};
  const Vec3 a(30, 16, 60), b(90, 16, 60), c(90, 64, 60), d(30, 64, 60);
  s.heat_in = {{a, b, c, 0.05}, {a, c, d, 0.05}};  // counter-clockwise seen from +z
  return s;
}

std::vector<Channel> block_bores() {
  auto bore = [](double y, double z, double d) {
    Channel c;
    c.axis = Segment{Vec3(0, y, z), Vec3(120, y, z)};
    c.radius = d / 2;
    c.coolant = 40;
    return c;
  };
  return {bore(20, 45, 10), bore(40, 47, 8), bore(61, 43, 10)};
}

struct Reference {
  Samples samples;
  std::vector<double> T;
};

Reference patch_reference() {
  std::ifstream in(MTCS_TEST_DATA + "/thermal/patch_samples.csv");
  REQUIRE(in);
  std::string line;
  std::getline(in, line);  // header x,y,z,T
  Reference r;
  while (std::getline(in, line)) {
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream row(line);
    double x, y, z, t;
    row >> x >> y >> z >> t;
    r.samples.points.emplace_back(x, y, z);
    r.samples.weights.push_back(4.0);  // 2 mm grid
    r.T.push_back(t);
  }
  REQUIRE(r.T.size() == 720);
  return r;
}

struct Comparison {
  double rms = 0, max = 0, mean_diff = 0, std_diff = 0, spearman = 0;
};



double mean_of(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x;
  return s / double(v.size());
}
double std_of(const std::vector<double>& v) {
  const double m = mean_of(v);
  double s = 0;
  for (double x : v) s += (x - m) * (x - m);
  return std::sqrt(s / double(v.size()));
}

Comparison compare(const std::vector<double>& model, const std::vector<double>& ref) {
  Comparison c;
  for (std::size_t i = 0; i < ref.size(); ++i) {
    const double d = model[i] - ref[i];
    c.rms += d * d;
    c.max = std::max(c.max, std::abs(d));
  }
  c.rms = std::sqrt(c.rms / double(ref.size()));
  c.mean_diff = mean_of(model) - mean_of(ref);
  c.std_diff = std_of(model) - std_of(ref);
  c.spearman = mtcs_test::spearman(model, ref);
  return c;
}

}  // namespace

TEST_CASE("line sinks on the block case against FreeFem++ P2 at the 720 patch samples") {
  const Reference ref = patch_reference();
  const Setting setting = block_setting();
  const auto bores = block_bores();
  // Two kinds of bar, kept apart. `target`: an RMS error fixed outside this code (the reference
  // study's T1 4.5 K and T2d 0.05 K; the 0.2 K for the in-loop tier, T2d with 4 elements).
  // `guard_*`: regression guards at what this code measured (experiments/thermal/line_sinks.md,
  // cfa921a) plus 5 %, which catch a change, not a physics error. T2 has no target it meets: the
  // study's 1.2 K against 1.300 K here (without dipoles the wall is not isothermal), so only a
  // guard. T2d with 12 elements meets the study's 0.05 K with two image levels at the samples.
  struct Bar { Tier tier; int elements, sample_images; double target, guard_rms, guard_max, guard_spearman; };
  constexpr double none = std::numeric_limits<double>::infinity();
  const Bar bars[] = {
      {Tier::T1, 1, 0, 4.5, 1.05 * 2.3631, 1.05 * 5.5453, 0.955 - 0.05 * (1 - 0.955)},
      {Tier::T2, 12, 0, none, 1.05 * 1.2995, 1.05 * 1.8040, 0.9948 - 0.05 * (1 - 0.9948)},
      {Tier::T2d, 4, 0, 0.2, 1.05 * 0.1391, 1.05 * 0.3520, 0.9989 - 0.05 * (1 - 0.9989)},
      {Tier::T2d, 12, 2, 0.05, 1.05 * 0.031, 1.05 * 0.050, 0.99996 - 0.05 * (1 - 0.99996)},
  };
  for (const Bar& bar : bars) {
    LineSinkOptions o;
    o.tier = bar.tier;
    o.elements = bar.elements;
    o.sample_images = bar.sample_images;
    const LineSinkModel model(setting, ref.samples, o);
    LineSinkCache cache;
    const LineSinkSolution sol = model.solve(bores, cache);
    const Comparison c = compare(sol.temperature, ref.T);
    INFO("tier " << int(bar.tier) << " M " << bar.elements << ": RMS " << c.rms << " max " << c.max
                 << " dmean " << c.mean_diff << " dstd " << c.std_diff << " spearman " << c.spearman
                 << " bores " << sol.channel_heat[0] + sol.channel_heat[1] + sol.channel_heat[2]
                 << " faces " << sol.face_heat);
    if (std::isfinite(bar.target)) CHECK(c.rms <= bar.target);
    CHECK(c.rms <= bar.guard_rms);
    CHECK(c.max <= bar.guard_max);
    CHECK(c.spearman >= bar.guard_spearman);
    // Energy balance: what enters leaves through the bores and the faces.
    double bores_heat = 0;
    for (double q : sol.channel_heat) bores_heat += q;
    CHECK(bores_heat + sol.face_heat == Approx(144.0).epsilon(1e-9));
    CHECK(sol.heat_in == Approx(144.0).epsilon(1e-12));
    // The reference's balance: bores 137.82 W, convection 6.18 W (T2d: 6.22-6.24 W; the faces'
    // mean temperature is sampled on a 4 x 4 grid, hence 2 %).
    if (bar.tier == Tier::T2d) CHECK(sol.face_heat == Approx(6.18).epsilon(0.02));
  }
}

namespace {

struct ClosedFormRow {
  std::string id, kind;
  double D = 0, z = 0, w = 0, k = 0, q = 0, expected = 0, fem = 0;
  bool judge_expected = false;
};

std::vector<ClosedFormRow> closed_forms() {
  std::ifstream in(MTCS_TEST_DATA + "/thermal/closed_form_2d.csv");
  REQUIRE(in);
  std::string line;
  std::getline(in, line);
  std::vector<ClosedFormRow> rows;
  while (std::getline(in, line)) {
    std::vector<std::string> f;
    std::string cell;
    std::istringstream row(line);
    while (std::getline(row, cell, ',')) f.push_back(cell);
    auto num = [&](int i) { return f[i].empty() ? 0.0 : std::stod(f[i]); };
    ClosedFormRow r;
    r.id = f[0];
    r.kind = f[1];
    r.D = num(2), r.z = num(3), r.w = num(4), r.k = num(5), r.q = num(6);
    r.expected = num(7), r.fem = num(8);
    r.judge_expected = f[10] == "expected";
    rows.push_back(r);
  }
  REQUIRE(rows.size() == 18);
  return rows;
}

Samples one_point(const Vec3& p) {
  Samples s;
  s.points = {p};
  s.weights = {1};
  return s;
}

LineSinkOptions tier(Tier t, int elements = 4) {
  LineSinkOptions o;
  o.tier = t;
  o.elements = elements;
  return o;
}

}  // namespace

// The far faces of the "open" cases, so far that their unpaired images, each the bores' whole
// charge Q at 2 kFar, shift the field by Q / (4 pi k kFar): 1e-4 K for 81 bores 3 m long.
constexpr double kFar = 1e9;

// A half-space: the isothermal face z = 0 and adiabatic faces kFar away, summed with one
// level of images and no far lattice (the level scheme's far part assumes a compact block).
Setting half_space(double k) {
  Setting s;
  s.block = {Vec3(-kFar, -kFar, -kFar), Vec3(kFar, kFar, 0)};
  s.conductivity = k;
  for (auto& f : s.faces) f = {0, 0};
  s.faces[int(BlockFace::PosZ)] = {std::numeric_limits<double>::infinity(), 0};
  return s;
}

LineSinkOptions open_space(Tier t, int images) {
  LineSinkOptions o = tier(t);
  o.images = images;
  o.far_images = 0;
  return o;
}

TEST_CASE("one bore under an isothermal face: shape factor 2 pi / acosh(2z/D)") {
  for (const ClosedFormRow& r : closed_forms()) {
    if (r.id.rfind("hole_iso", 0) != 0) continue;
    // A bore 3000 mm long: its ends change the middle by (2z/L)^2 ~ 1e-4.
    Channel bore;
    bore.axis = Segment{Vec3(-1500, 0, -r.z), Vec3(1500, 0, -r.z)};
    bore.radius = r.D / 2;
    bore.coolant = 1;
    for (Tier t : {Tier::T2, Tier::T2d}) {
      // The middle element of 5 (each 600 mm), where the bore is as good as infinite.
      LineSinkOptions o = open_space(t, 1);
      o.elements = 5;
      const LineSinkModel model(half_space(1.0), one_point(Vec3(0, 0, 0)), o);
      LineSinkCache cache;
      const LineSinkSolution sol = model.solve(std::vector<Channel>{bore}, cache);
      // The bore at 1 heats the face at 0: the heat into the coolant is -S per length.
      const double S = -sol.channel_heat[0] / 3000;
      INFO(r.id << " tier " << int(t) << " S " << S << " expected " << r.expected);
      if (t == Tier::T2) {
        // A line sink at the centre, wall mean collocated: the textbook 2 pi / ln(4z/D), but
        // for the four-point wall mean's fourth harmonic, (D/4z)^4.
        CHECK(S == Approx(2 * std::numbers::pi / std::log(4 * r.z / r.D)).epsilon(std::pow(r.D / (4 * r.z), 4) + 2e-3));
      } else {
        // The dipole takes the first harmonic: left is O((D/4z)^4) of the log.
        CHECK(S == Approx(r.expected).epsilon(std::pow(r.D / (4 * r.z), 4) + 2e-3));
      }
      // The face stays at its ambient: the sample on it reads 0, but for the five far faces'
      // images of the bore, each at most S L / (4 pi kFar).
      CHECK(std::abs(sol.temperature[0]) < 5 * S * 3000 / (4 * std::numbers::pi * kFar));
    }
  }
}

TEST_CASE("two bores in a wide slab: shape factor 2 pi / acosh((4w^2 - D1^2 - D2^2) / (2 D1 D2))") {
  // Notes 4.3 (Incropera Table 4.1), infinite medium: no faces, net heat zero.
  const double w = 20, D1 = 10, D2 = 8;
  Setting s = half_space(1.0);
  s.faces[int(BlockFace::PosZ)] = {0, 0};
  s.block.max.z() = kFar;
  auto bore = [](double y, double D, double T) {
    Channel c;
    c.axis = Segment{Vec3(-1500, y, 0), Vec3(1500, y, 0)};
    c.radius = D / 2;
    c.coolant = T;
    return c;
  };
  const std::vector<Channel> bores{bore(0, D1, 1), bore(w, D2, 0)};
  const double exact = 2 * std::numbers::pi / std::acosh((4 * w * w - D1 * D1 - D2 * D2) / (2 * D1 * D2));
  const LineSinkModel t2(s, one_point(Vec3(0, 0, 100)), open_space(Tier::T2, 0));
  const LineSinkModel t2d(s, one_point(Vec3(0, 0, 100)), open_space(Tier::T2d, 0));
  LineSinkCache c2, c2d;
  const LineSinkSolution a = t2.solve(bores, c2), b = t2d.solve(bores, c2d);
  CHECK(a.channel_heat[0] == Approx(-a.channel_heat[1]).epsilon(1e-9));
  // Line sinks at the centres: 2 pi / ln(w^2 / (R1 R2)) (the cylinders' offset is ignored).
  CHECK(-a.channel_heat[0] / 3000 == Approx(2 * std::numbers::pi / std::log(w * w / (D1 * D2 / 4))).epsilon(2e-3));
  // With the dipoles: within (R/w)^4 of the exact value.
  CHECK(-b.channel_heat[0] / 3000 == Approx(exact).epsilon(std::pow(D1 / (2 * w), 4) + 2e-3));
}

TEST_CASE("a row of bores under a heated face: surface spread against the FEM") {
  // 41 bores at pitch w under a heated strip 41 w wide, adiabatic faces far away: over the
  // middle bore the field is the periodic row's (the FEM's periodic cell; its adiabatic bottom
  // 3w down changes the spread by exp(-6 pi)).
  for (const ClosedFormRow& r : closed_forms()) {
    if (r.kind != "surface_spread_K") continue;
    Setting s = half_space(r.k);
    s.faces[int(BlockFace::PosZ)] = {0, 0};
    const double half = 20.5 * r.w;
    const Vec3 a(-1500, -half, 0), b(1500, -half, 0), c(1500, half, 0), d(-1500, half, 0);
    s.heat_in = {{a, b, c, r.q}, {a, c, d, r.q}};
    Samples line;
    for (int i = 0; i <= 60; ++i) line.points.emplace_back(0, r.w * (i / 60.0 - 0.5), 0), line.weights.push_back(1);
    std::vector<Channel> row;
    for (int j = -20; j <= 20; ++j) {
      Channel ch;
      ch.axis = Segment{Vec3(-1500, j * r.w, -r.z), Vec3(1500, j * r.w, -r.z)};
      ch.radius = r.D / 2;
      ch.coolant = 0;
      row.push_back(ch);
    }
    LineSinkOptions o = open_space(Tier::T2d, 1);
    o.elements = 1;
    const LineSinkModel model(s, line, o);
    LineSinkCache cache;
    const auto T = model.temperatures(row, cache);
    const double spread = *std::max_element(T.begin(), T.end()) - *std::min_element(T.begin(), T.end());
    INFO(r.id << " D " << r.D << " w " << r.w << " spread " << spread << " fem " << r.fem
              << " line-sink formula " << r.expected);
    // Thin bores (D/w <= 1/15): the FEM within 1 % (measured 0.1 %). Thick ones: the dipole
    // captures the first harmonic; what is left grows like (D/w)^2 (measured: -3 % at 1/3,
    // -11 % at 1/2).
    CHECK(spread == Approx(r.fem).epsilon(std::max(0.01, 0.5 * std::pow(r.D / r.w, 2))));
  }
}

TEST_CASE("a row of bores under an isothermal face: shape factor per bore against the FEM") {
  // 81 bores at pitch w, the face at 0; the middle bore's heat per length is the periodic row's
  // but for the missing bores beyond, each a dipole with its image: ~(2z/w)^2 / (2 * 40) relative.
  for (const ClosedFormRow& r : closed_forms()) {
    if (r.kind != "S_per_length_per_hole") continue;
    std::vector<Channel> row;
    for (int j = -40; j <= 40; ++j) {
      Channel ch;
      ch.axis = Segment{Vec3(-1500, j * r.w, -r.z), Vec3(1500, j * r.w, -r.z)};
      ch.radius = r.D / 2;
      ch.coolant = 1;
      row.push_back(ch);
    }
    LineSinkOptions o = open_space(Tier::T2d, 1);
    o.elements = 1;
    const LineSinkModel model(half_space(1.0), one_point(Vec3(0, 0, 0)), o);
    LineSinkCache cache;
    const auto sol = model.solve(row, cache);
    const double S = -sol.channel_heat[40] / 3000;
    const double reference = r.judge_expected ? r.expected : r.fem;
    INFO(r.id << " D " << r.D << " z " << r.z << " w " << r.w << " S " << S << " fem " << r.fem
              << " formula " << r.expected);
    // The 80 neighbours stand for the infinite row: the missing ones raise S by ~0.6 %
    // (measured +0.6 to +0.8 %); thick bores add a (D/w)^2-order term as for the spread.
    CHECK(S == Approx(reference).epsilon(std::max(0.01, 0.5 * std::pow(r.D / r.w, 2))));
  }
}

TEST_CASE("line sinks: stiff and extreme inputs stay finite and reach their limits") {
  const Reference ref = patch_reference();
  const Setting setting = block_setting();
  const auto bores = block_bores();
  auto finite = [](const std::vector<double>& v) {
    return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
  };
  // The block model, built only by the sections that use it (each section reruns this body).
  std::optional<LineSinkModel> block_model;
  LineSinkCache cache;
  auto model_of_block = [&]() -> const LineSinkModel& {
    if (!block_model) block_model.emplace(setting, ref.samples);
    return *block_model;
  };

  SECTION("a bore of aspect ratio 1e6 under an isothermal face") {
    Channel c;
    c.axis = Segment{Vec3(-1000, 0, -15), Vec3(1000, 0, -15)};  // length 2000, radius 1e-3
    c.radius = 1e-3;
    c.coolant = 1;
    const LineSinkModel m(half_space(1.0), one_point(Vec3(0, 0, 0)), open_space(Tier::T2d, 1));
    LineSinkCache cc;
    const auto sol = m.solve(std::vector<Channel>{c}, cc);
    REQUIRE(std::isfinite(sol.channel_heat[0]));
    // The ends cost (2z/L)^2 relative, the far faces 1e-4: per mille.
    CHECK(-sol.channel_heat[0] / 2000 == Approx(2 * std::numbers::pi / std::acosh(2 * 15 / 2e-3)).epsilon(1e-3));
  }
  SECTION("a bore 1e-3 mm under the heated patch") {
    auto near = bores;
    near[1].axis.p0.z() = near[1].axis.p1.z() = 60 - near[1].radius - 1e-3;
    const auto T = model_of_block().temperatures(near, cache);
    REQUIRE(finite(T));
    // The samples right above it (y = 39, 41) are the coolest of the patch and near the coolant.
    const auto coolest = std::min_element(T.begin(), T.end()) - T.begin();
    CHECK(std::abs(ref.samples.points[coolest].y() - 40) <= 1.0 + 1e-9);
    CHECK(T[coolest] < 43);
    // The true field stays above the coolant; the sinks' first-harmonic wall undershoots it
    // by 0.33 K here (the patch's flux 1e-3 mm above the wall has every harmonic).
    CHECK(T[coolest] > 39.5);
  }
  SECTION("film -> 0: the bores take no heat, the faces take all") {
    auto dry = bores;
    for (auto& b : dry) b.film = 0;
    const LineSinkModel& model = model_of_block();
    const auto sol = model.solve(dry, cache);
    REQUIRE(finite(sol.temperature));
    for (double q : sol.channel_heat) CHECK(std::abs(q) < 1e-9);
    CHECK(sol.face_heat == Approx(144).epsilon(1e-9));
    // And continuously: a film of 1e-12 W/(mm^2 K) is the same within 1e-6 K.
    auto almost = bores;
    for (auto& b : almost) b.film = 1e-12;
    const auto T = model.temperatures(almost, cache);
    for (std::size_t i = 0; i < T.size(); ++i) CHECK(T[i] == Approx(sol.temperature[i]).epsilon(1e-6));
  }
  SECTION("film -> infinity: the Dirichlet limit, continuously") {
    const LineSinkModel& model = model_of_block();
    const auto base = model.temperatures(bores, cache);
    auto wet = bores;
    for (auto& b : wet) b.film = 1e9;
    const auto T = model.temperatures(wet, cache);
    for (std::size_t i = 0; i < T.size(); ++i) CHECK(T[i] == Approx(base[i]).margin(1e-5));
    // A finite film warms the patch: the film's drop adds to the wall's.
    for (auto& b : wet) b.film = 1e-3;  // 1000 W/(m^2 K)
    const auto warm = model.temperatures(wet, cache);
    for (std::size_t i = 0; i < T.size(); ++i) CHECK(warm[i] > base[i]);
  }
  SECTION("bores end to end on one axis equal the whole bore cut the same way") {
    // Every bore cut at x = 60 into two channels of 4 elements: the same 8 elements per axis
    // as the whole bores with 8, so the same field but for rounding (float columns: 1e-4 K).
    std::vector<Channel> split;
    for (Channel whole : bores) {
      Channel second = whole;
      whole.axis.p1.x() = 60;
      second.axis.p0.x() = 60;
      split.push_back(whole);
      split.push_back(second);
    }
    LineSinkOptions o;
    o.pair_far = 0;  // exact pairs: the whole bore's own block (halves' pair) is exact
    const LineSinkModel halves(setting, ref.samples, o);
    o.elements = 8;
    const LineSinkModel whole(setting, ref.samples, o);
    LineSinkCache c1, c2;
    const auto Th = halves.solve(split, c1);
    const auto Tw = whole.solve(bores, c2);
    REQUIRE(finite(Th.temperature));
    for (std::size_t i = 0; i < Tw.temperature.size(); ++i)
      CHECK(Th.temperature[i] == Approx(Tw.temperature[i]).margin(1e-4));
    for (int k = 0; k < 3; ++k)
      CHECK(Th.channel_heat[2 * k] + Th.channel_heat[2 * k + 1] == Approx(Tw.channel_heat[k]).epsilon(1e-6));
  }
  SECTION("a bore reaching out of the block counts only inside the steel") {
    auto out = bores;
    out[0].axis.p0.x() = -30;  // 30 mm of the bore in the air
    const auto T = model_of_block().temperatures(out, cache);
    const auto base = model_of_block().temperatures(bores, cache);
    CHECK(T == base);
    auto away = bores;
    away[0].axis.p0.z() = away[0].axis.p1.z() = 70;  // above the block
    CHECK_THROWS_AS(model_of_block().temperatures(away, cache), std::invalid_argument);
  }
  SECTION("everything moved by 1e4 mm in each axis") {
    Setting far = setting;
    const Vec3 d(1e4, 1e4, 1e4);
    far.block.min += d, far.block.max += d;
    for (auto& t : far.heat_in) t.a += d, t.b += d, t.c += d;
    Samples s = ref.samples;
    for (auto& p : s.points) p += d;
    auto moved = bores;
    for (auto& b : moved) b.axis.p0 += d, b.axis.p1 += d;
    LineSinkOptions o;
    o.single_precision = false;
    const LineSinkModel m(far, s, o), m0(setting, ref.samples, o);
    LineSinkCache c1, c2;
    const auto T = m.temperatures(moved, c1), T0 = m0.temperatures(bores, c2);
    for (std::size_t i = 0; i < T.size(); ++i) CHECK(T[i] == Approx(T0[i]).margin(1e-6));
  }
}

TEST_CASE("line sinks: an incremental evaluation equals a full one, bit for bit") {
  const Reference ref = patch_reference();
  const Setting setting = block_setting();
  const auto bores = block_bores();
  for (Tier t : {Tier::T1, Tier::T2, Tier::T2d}) {
    const LineSinkModel model(setting, ref.samples, tier(t));
    LineSinkCache warm;
    model.solve(bores, warm);
    auto moved = bores;
    moved[0].axis.p0.z() += 1, moved[0].axis.p1.z() += 1;
    moved[2].radius = 4;
    moved[1].coolant = 30;  // not in the key: reuses the columns
    const auto incremental = model.solve(moved, warm);
    CHECK(warm.channels_reused == 1);
    CHECK(warm.channels_computed == 5);
    LineSinkCache cold;
    const auto full = model.solve(moved, cold);
    CHECK(incremental.temperature == full.temperature);
    CHECK(incremental.channel_heat == full.channel_heat);
  }
}

// The far expansion at samples and face points (default far_expansion 0.35) against the closed
// forms everywhere (0): on the block it moves no sample by more than 2 mK, far below the
// model's 0.14 K RMS against FreeFem++ (experiments/thermal/columns.md).
TEST_CASE("line sinks: the far expansion at the samples changes the block's temperatures by < 2 mK") {
  const Reference ref = patch_reference();
  LineSinkOptions exact;
  exact.far_expansion = 0;
  const LineSinkModel with_far(block_setting(), ref.samples), without(block_setting(), ref.samples, exact);
  for (double dy : {0.0, 5.0}) {
    auto bores = block_bores();
    for (auto& b : bores) b.axis.p0.y() += dy, b.axis.p1.y() += dy;
    LineSinkCache c1, c2;
    const auto a = with_far.solve(bores, c1).temperature, b = without.solve(bores, c2).temperature;
    double worst = 0;
    for (std::size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::abs(a[i] - b[i]));
    INFO("dy " << dy << " max |dT| " << worst);
    CHECK(worst < 2e-3);
    CHECK(worst > 0);  // the expansion is used on the block
  }
}

// The cache keeps several layouts' blocks (an ES child's parent is rarely the layout just
// before it): a layout seen two evaluations ago still hits, and a cache squeezed by a tiny
// budget (evicting on every call) still gives the cold result bit for bit.
TEST_CASE("line sinks: the cache keeps earlier layouts and evicts without changing a result") {
  const Reference ref = patch_reference();
  const LineSinkModel model(block_setting(), ref.samples);
  const auto parent = block_bores();
  auto other = parent;
  for (auto& b : other) b.axis.p0.y() += 2, b.axis.p1.y() += 2;
  auto child = parent;
  child[1].axis.p0.z() -= 1, child[1].axis.p1.z() -= 1;
  LineSinkCache warm, squeezed(1);
  model.solve(parent, warm);
  model.solve(other, warm);
  const std::size_t computed = warm.channels_computed;
  const auto incremental = model.solve(child, warm);
  CHECK(warm.channels_computed == computed + 1);  // the parent's two other bores were kept
  LineSinkCache cold;
  const auto full = model.solve(child, cold);
  CHECK(incremental.temperature == full.temperature);
  using Layout = std::remove_cvref_t<decltype(parent)>;
  for (const Layout* layout : {&parent, static_cast<const Layout*>(&other), static_cast<const Layout*>(&child), &parent,
                               static_cast<const Layout*>(&child)}) {
    const auto a = model.solve(*layout, squeezed);
    LineSinkCache fresh;
    CHECK(a.temperature == model.solve(*layout, fresh).temperature);
  }
}

TEST_CASE("line sinks: single-precision columns cost under 1e-4 K") {
  const Reference ref = patch_reference();
  LineSinkOptions o;
  o.pair_far = 0;  // the double path's pairs are exact (pair_far_test.cpp measures the multipoles)
  const LineSinkModel f(block_setting(), ref.samples, o);
  o.single_precision = false;
  const LineSinkModel d(block_setting(), ref.samples, o);
  LineSinkCache c1, c2;
  const auto Tf = f.temperatures(block_bores(), c1), Td = d.temperatures(block_bores(), c2);
  double worst = 0;
  for (std::size_t i = 0; i < Tf.size(); ++i) worst = std::max(worst, std::abs(Tf[i] - Td[i]));
  CHECK(worst < 1e-4);
  CHECK(worst > 0);  // the float path is really taken
}

TEST_CASE("line sinks: a bore inside another's bore takes no heat and changes nothing") {
  // Two bores 2.5 mm apart joined by a 2.5 mm jog, all 8 mm: the jog lies inside the first
  // bore (its ends within 4 mm of that axis), so it has no steel wall. Left in, its collocation
  // points sat in the other's coolant (a ribbed_box layout at 8 elements: -1 363 to 4 197 C).
  const Reference ref = patch_reference();
  auto bore = [](Vec3 a, Vec3 b) {
    Channel c;
    c.axis = Segment{a, b};
    c.radius = 4;
    c.coolant = 40;
    return c;
  };
  const Channel first = bore({0, 30, 45}, {60, 30, 45}), jog = bore({60, 30, 45}, {60, 32.5, 45}),
                second = bore({60, 32.5, 45}, {120, 32.5, 45}), other = bore({0, 60, 45}, {120, 60, 45});
  for (const int elements : {4, 8, 12}) {
    INFO(elements << " elements");
    LineSinkOptions o;
    o.elements = elements;
    const LineSinkModel model(block_setting(), ref.samples, o);
    LineSinkCache a, b;
    const auto with = model.solve(std::vector<Channel>{first, jog, second, other}, a);
    const auto without = model.solve(std::vector<Channel>{first, second, other}, b);
    CHECK(with.temperature == without.temperature);
    REQUIRE(with.channel_heat.size() == 4);
    CHECK(with.channel_heat[1] == 0);
    CHECK(with.channel_heat[0] == without.channel_heat[0]);
    CHECK(with.channel_heat[3] == without.channel_heat[2]);
    // Identical bores: the first stays, the second adds nothing.
    LineSinkCache c;
    const auto twice = model.solve(std::vector<Channel>{first, second, other, other}, c);
    CHECK(twice.temperature == without.temperature);
    CHECK(twice.channel_heat[3] == 0);
  }
}
