// mtcs-microbench: Google Benchmark timings of single kernels against their peers in the same
// run (the same inputs, interleaved by the library's repetitions): the cylinder distance kernel
// against FCL's GJK, and the hypervolume against pagmo's. The end-to-end benchmarks with errors
// against certified data stay in mtcs-bench; this is the per-call cost with the library's
// statistics (--benchmark_repetitions, --benchmark_format=csv).

#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "../fcl_peer.h"
#include "../pagmo_peer.h"
#include "mtcs/geometry/cylinder_distance.h"
#include "mtcs/opt/hypervolume.h"

namespace {

using mtcs::geometry::Cylinder;
using mtcs::geometry::Vec3;

// 1024 cylinder pairs in a 100 mm cube, radii 1-10 mm, lengths up to 100 mm (seed 1): the
// drilled-bore scale of the molds.
std::vector<std::pair<Cylinder, Cylinder>> pairs() {
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> pos(0, 100), radius(1, 10);
  auto cylinder = [&] { return Cylinder{Vec3(pos(rng), pos(rng), pos(rng)), Vec3(pos(rng), pos(rng), pos(rng)), radius(rng)}; };
  std::vector<std::pair<Cylinder, Cylinder>> out;
  for (int i = 0; i < 1024; ++i) out.emplace_back(cylinder(), cylinder());
  return out;
}

void BM_cylinder_distance_mtcs(benchmark::State& state) {
  const auto ps = pairs();
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& [a, b] = ps[i++ & 1023];
    benchmark::DoNotOptimize(mtcs::geometry::distance(a, b).distance);
  }
}
BENCHMARK(BM_cylinder_distance_mtcs);

void BM_cylinder_distance_fcl(benchmark::State& state) {
  const auto ps = pairs();
  std::vector<mtcs::bench::FclPair> fcl;  // FCL's objects built once, outside the timing
  for (const auto& [a, b] : ps) fcl.emplace_back(a, b);
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(fcl[i++ & 1023].distance());
}
BENCHMARK(BM_cylinder_distance_fcl);

// n mutually non-dominated points on the simplex-like front sum(x) = 1 (d objectives, seed 1).
std::vector<mtcs::opt::Point> front(int n, int d) {
  std::mt19937_64 rng(1);
  std::exponential_distribution<double> e(1);
  std::vector<mtcs::opt::Point> out;
  for (int i = 0; i < n; ++i) {
    mtcs::opt::Point p(static_cast<std::size_t>(d));
    double s = 0;
    for (double& x : p) s += x = e(rng);
    for (double& x : p) x /= s;
    out.push_back(p);
  }
  return out;
}

void BM_hypervolume_mtcs(benchmark::State& state) {
  const int d = int(state.range(1));
  const auto f = front(int(state.range(0)), d);
  const mtcs::opt::Point ref(std::size_t(d), 1.1);
  for (auto _ : state) benchmark::DoNotOptimize(mtcs::opt::hypervolume(f, ref));
}
BENCHMARK(BM_hypervolume_mtcs)->Args({100, 2})->Args({100, 3})->Args({1000, 3})->Args({100, 4});

void BM_hypervolume_pagmo(benchmark::State& state) {
  const int d = int(state.range(1));
  const auto f = front(int(state.range(0)), d);
  const std::vector<double> ref(std::size_t(d), 1.1);
  for (auto _ : state) benchmark::DoNotOptimize(mtcs::bench::pagmo_hypervolume(f, ref));
}
BENCHMARK(BM_hypervolume_pagmo)->Args({100, 2})->Args({100, 3})->Args({1000, 3})->Args({100, 4});

}  // namespace

BENCHMARK_MAIN();
