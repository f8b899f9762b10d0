// Kernel bench (plate_solve.md, section 4): one channel's float columns at the plate's 1 166
// heated samples x 7 image slots (main's chunked far expansion at 0.35), 4 channels, best of 7 x
// 300 calls each; MORTON=1 in the environment orders the samples in Morton order first.
// Build from the repository's root after building mtcs_thermal:
//   g++ -std=c++20 -O2 -Isrc -Iinclude -I/usr/include/eigen3 experiments/thermal/plate_kernel_bench.cpp \
//     build/src/thermal/libmtcs_thermal.a build/src/geometry/libmtcs_geometry.a -o /tmp/plate_kernel_bench
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <vector>
#include <cstdlib>
#include <cstdint>
#include "thermal/line_sink_tables.h"
using namespace mtcs::thermal;
int main() {
  std::vector<Vec3> pts;
  const Vec3 lo(50, 25, 105), hi(250, 175, 108), size = hi - lo;
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    const int ni = std::max(1, int(std::ceil(size[i] / 5.5))), nj = std::max(1, int(std::ceil(size[j] / 5.5)));
    for (const double plane : {lo[k], hi[k]}) {
      if (k == 2 && plane == hi[k]) continue;
      for (int a = 0; a < ni; ++a) for (int b = 0; b < nj; ++b) { Vec3 p; p[k] = plane, p[i] = lo[i] + (a + 0.5) * size[i] / ni, p[j] = lo[j] + (b + 0.5) * size[j] / nj; pts.push_back(p); }
    }
  }
  if (std::getenv("MORTON")) {  // compact chunks: the samples in Morton order of 1 mm cells
    auto key = [](const Vec3& p) { std::uint64_t k = 0; const std::uint32_t c[3] = {std::uint32_t(p.x()), std::uint32_t(p.y()), std::uint32_t(p.z())};
      for (int b = 9; b >= 0; --b) for (int a = 0; a < 3; ++a) k = (k << 1) | ((c[a] >> b) & 1); return k; };
    std::stable_sort(pts.begin(), pts.end(), [&](const Vec3& a, const Vec3& b) { return key(a) < key(b); });
  }
  std::array<double, 6> sign; sign.fill(1.0);
  const auto images = block_images(Box{Vec3(0, 0, 0), Vec3(300, 200, 120)}, sign, 1);
  Vec3 origin = Vec3::Zero(); for (auto& p : pts) origin += p / double(pts.size());
  PointSet ps; for (auto& p : pts) ps.add(images, p, 1e-9, 1.0, origin), ps.close_target();
  ps.make_slots(); ps.make_chunk_boxes();
  const FarChunks far{ps.chunk_box.data(), ps.chunk, 0.35f};
  const std::size_t T = ps.targets();
  double total_best = 0; float checksum = 0;
  const Vec3 ends[4][2] = {{Vec3(0, 60, 90), Vec3(300, 60, 90)}, {Vec3(100, 0, 80), Vec3(100, 200, 80)}, {Vec3(0, 140, 97), Vec3(180, 140, 97)}, {Vec3(30, 10, 60), Vec3(270, 190, 20)}};
  for (auto& e : ends) {
    Channel c; c.axis = mtcs::geometry::Segment{e[0], e[1]}; c.radius = 4;
    const ChannelAxis axis = channel_axis(c, 4);
    std::vector<float> out(T * 12);
    double best = 1e30;
    for (int run = 0; run < 7; ++run) {
      std::fill(out.begin(), out.end(), 0.0f);
      const std::clock_t t0 = std::clock();
      for (int i = 0; i < 300; ++i) element_fields_float_slots(axis, origin, 3, ps.sx.data(), ps.sy.data(), ps.sz.data(), ps.sw.data(), T, ps.slots, out.data(), &far);
      best = std::min(best, double(std::clock() - t0) / CLOCKS_PER_SEC / 300);
    }
    for (float v : out) checksum += v;
    std::printf("channel %.0f,%.0f,%.0f-%.0f,%.0f,%.0f: %.4f ms\n", e[0].x(), e[0].y(), e[0].z(), e[1].x(), e[1].y(), e[1].z(), 1e3 * best);
    total_best += best;
  }
  std::printf("sum of best %.4f ms (checksum %g)\n", 1e3 * total_best, checksum);
}
