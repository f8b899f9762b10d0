#!/usr/bin/env bash
# How often the circle minimiser misses the global minimum: circle_circle_distance,
# circle_disk_distance and circle_line_distance against the dense-sampling oracle of
# tests/geometry/circle_distance_test.cpp (here 6 000 samples), on random cases drawn in sequence.
#   bash experiments/ci/circle_misses.sh [SEED] [CASES]     (after scripts/build.sh)
set -euo pipefail
cd "$(dirname "$0")/../.."
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 - "$work/h.cpp" <<'PY'
import sys
src = open('tests/geometry/circle_distance_test.cpp').read()
start = src.index('namespace {'); end = src.index('}  // namespace', start) + len('}  // namespace')
helpers = src[start:end].replace('const int n = 20000;', 'const int n = 6000;')
open(sys.argv[1], 'w').write('''#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include "geometry/circle_distance.h"
using namespace mtcs::geometry;
''' + helpers + '''
int main(int argc, char** argv) {
  std::mt19937_64 rng(argc > 1 ? std::atoi(argv[1]) : 11);
  std::uniform_real_distribution<double> u(-3, 3), r(0.05, 3);
  auto v = [&] { const double x = u(rng), y = u(rng), z = u(rng); return Vec3(x, y, z); };
  int miss_l = 0, miss_c = 0, miss_d = 0;
  double worst_c = 0, worst_d = 0;
  const int n = argc > 2 ? std::atoi(argv[2]) : 3000;
  for (int i = 0; i < n; ++i) {
    const Circle c{v(), v().normalized(), r(rng)};
    const Circle o{v(), v().normalized(), r(rng)};
    const Vec3 lo = v(), ld = v();
    if (circle_line_distance(c, lo, ld).distance > oracle(c, [&](const Vec3& p) { return point_line(p, lo, ld); }) + 1e-10) ++miss_l;
    const double dc = circle_circle_distance(c, o).distance, rc = oracle(c, [&](const Vec3& p) { return point_circle(p, o, false); });
    if (dc > rc + 1e-10) ++miss_c, worst_c = std::max(worst_c, dc - rc);
    const double dd = circle_disk_distance(c, o).distance, rd = oracle(c, [&](const Vec3& p) { return point_circle(p, o, true); });
    if (dd > rd + 1e-10) ++miss_d, worst_d = std::max(worst_d, dd - rd);
  }
  std::printf("%d cases: circle-line misses %d; circle-circle %d (worst +%.3g); circle-disk %d (worst +%.3g)\\n",
              n, miss_l, miss_c, worst_c, miss_d, worst_d);
}
''')
PY
g++ -O2 -std=gnu++20 -Iinclude -Isrc -isystem /usr/include/eigen3 "$work/h.cpp" build/src/geometry/libmtcs_geometry.a \
  -lquadmath -o "$work/h"
"$work/h" "${1:-11}" "${2:-3000}"
