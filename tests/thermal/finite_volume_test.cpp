// T3, the finite-volume reference, against independent references: the FreeFem++ P2 solution of
// the reference block (shared/cases/thermal), closed-form shape factors, and physical limits.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "mtcs/thermal/finite_volume.h"

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
  std::ifstream in(MTCS_TEST_DATA "/thermal/patch_samples.csv");
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
  return e;
}

double balance_error(const FvResult& r) {
  return std::abs(r.heat_in - r.heat_to_channels - r.heat_to_faces) / r.heat_in;
}

}  // namespace

TEST_CASE("finite volume: the reference block at 2 mm is near FreeFem's P2 solution", "[fv]") {
  const Reference ref = patch_samples();
  const FvResult r = solve_finite_volume(block_case(), ref.samples, {2.0});
  const Errors e = compare(r.temperature, ref);
  INFO("rms " << e.rms << " max " << e.max << " dmean " << e.mean << " dstd " << e.std << " s " << r.seconds
              << " it " << r.iterations);
  CHECK(r.heat_in == Approx(144.0).epsilon(1e-12));
  CHECK(balance_error(r) < 1e-6);
  CHECK(r.heat_to_channels == Approx(137.82).margin(0.3));
  CHECK(r.heat_to_faces == Approx(6.18).margin(0.3));
  CHECK(e.rms < 0.4);
}

// The error-versus-cost table of experiments/thermal/fv.md: run by hand, it prints CSV.
TEST_CASE("finite volume: error against run time on the reference block", "[.fv-table]") {
  const Reference ref = patch_samples();
  std::cout << "cell_mm,steel_cells,seconds,iterations,rms_K,max_K,dmean_K,dstd_K,heat_in_W,to_channels_W,"
               "to_faces_W,balance_rel\n";
  for (double cell : {4.0, 3.0, 2.0, 1.5, 1.0, 0.75}) {
    const FvResult r = solve_finite_volume(block_case(), ref.samples, {cell});
    const Errors e = compare(r.temperature, ref);
    std::cout << cell << ',' << r.steel_cells << ',' << r.seconds << ',' << r.iterations << ',' << e.rms << ','
              << e.max << ',' << e.mean << ',' << e.std << ',' << r.heat_in << ',' << r.heat_to_channels << ','
              << r.heat_to_faces << ',' << balance_error(r) << std::endl;
  }
}
