// The distance query must not allocate: it runs millions of times per optimisation, from many
// threads. Every global operator new in this test binary is counted.

#include <catch2/catch.hpp>
#include <atomic>
#include <cstdlib>
#include <new>
#include <random>

#include "mtcs/geometry/cylinder_distance.h"

namespace {
std::atomic<long> g_allocations{0};
}

void* operator new(std::size_t n) {
  ++g_allocations;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

using namespace mtcs::geometry;

TEST_CASE("distance queries do not allocate", "[geometry][cylinder]") {
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(-5, 5), r(0.01, 2);
  std::vector<std::pair<Cylinder, Cylinder>> pairs;
  for (int i = 0; i < 2000; ++i) {
    const double a0 = u(rng), a1 = u(rng), a2 = u(rng), a3 = u(rng), a4 = u(rng), a5 = u(rng);
    const double b0 = u(rng), b1 = u(rng), b2 = u(rng), b3 = u(rng), b4 = u(rng), b5 = u(rng);
    pairs.push_back({{{a0, a1, a2}, {a3, a4, a5}, r(rng)}, {{b0, b1, b2}, {b3, b4, b5}, r(rng)}});
  }
  // Touching pairs take the extended-precision path too.
  pairs.push_back({{{0, 0, 0}, {10, 0, 0}, 1}, {{0, 3, 0}, {10, 3, 0}, 2}});
  const long before = g_allocations.load();
  double sum = 0;
  for (const auto& [a, b] : pairs) {
    sum += distance(a, b).distance;
    sum += distance(a, b, {.upper_bound = 1}).distance;
  }
  const long after = g_allocations.load();
  CHECK(sum > 0);
  CHECK(after - before == 0);
}
