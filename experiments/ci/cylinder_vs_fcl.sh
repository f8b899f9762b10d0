#!/usr/bin/env bash
# Does the solid-cylinder kernel over-estimate a distance (the direction that would miss a
# clearance violation) where the circle minimiser misses basins (circle_misses.sh)? Random
# separated pairs against FCL's GJK, whose distance is that of two points on the shapes: an upper
# bound of the true one. Counts ours above FCL (a miss) and below it (FCL loose).
#   bash experiments/ci/cylinder_vs_fcl.sh [SEED] [PAIRS]     (after scripts/build.sh)
set -euo pipefail
cd "$(dirname "$0")/../.."
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat > "$work/c.cpp" <<'CPP'
#include <cstdio>
#include <cstdlib>
#include <random>
#include "mtcs/geometry/cylinder_distance.h"
#include "bench/fcl_peer.h"
using namespace mtcs::geometry;
int main(int argc, char** argv) {
  std::mt19937_64 rng(argc > 1 ? std::atoi(argv[1]) : 1);
  std::uniform_real_distribution<double> u(-3, 3), r(0.05, 3);
  auto v = [&] { const double x = u(rng), y = u(rng), z = u(rng); return Vec3(x, y, z); };
  const int n = argc > 2 ? std::atoi(argv[2]) : 100000;
  int over = 0, under = 0, apart = 0, loose = 0; double worst = 0;
  for (int i = 0; i < n; ++i) {
    const Vec3 a0 = v(), a1 = v(), b0 = v(), b1 = v();
    const Cylinder a{a0, a0 + 0.5 * (a1 - a0), r(rng)}, b{b0, b0 + 0.5 * (b1 - b0), r(rng)};
    const double ours = distance(a, b).distance;
    if (ours <= 0) continue;
    ++apart;
    const double f = mtcs::bench::FclPair(a, b).distance();
    if (ours > f + 1e-6) { ++over; if (ours - f > worst) worst = ours - f; if (over <= 5) std::printf("case %d: ours %.9g fcl %.9g\n", i, ours, f); }
    if (ours < f - 1e-6) ++under; if (f - ours > 1e-3) ++loose;
  }
  std::printf("%d pairs apart of %d: ours above FCL by >1e-6: %d (worst +%.3g); below: %d, below by >1e-3: %d\n", apart, n, over, worst, under, loose);
}
CPP
g++ -O2 -std=gnu++20 -Iinclude -I. -Isrc -isystem /usr/include/eigen3 "$work/c.cpp" build/bench/libmtcs_bench.a \
  build/src/geometry/libmtcs_geometry.a -lfcl -lccd -lquadmath -o "$work/c"
"$work/c" "${1:-1}" "${2:-100000}"
