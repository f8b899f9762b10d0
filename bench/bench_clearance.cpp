// Cylinder vs closed mesh: ours (SAH tree; exact, with the upper bound, and on a median-split
// tree) against FCL 0.7 (BVHModel<OBBRSS>, GJK per triangle) on the same meshes and certified
// cases in the same run. Each query is timed over `repeat` back-to-back
// calls (one clock read per batch); medians and 90th percentiles are over cases. Errors follow
// the certified cases' judge: distance from the answer to [dist_lo, dist_hi] over
// S = max(1, cylinder length, r, bbox diagonal); a verdict is wrong when "touching" (0) and
// "separated" (> 0) disagree with the interval.

#include "bench_clearance.h"

#include <algorithm>
#include <chrono>
#include <functional>
#include <iostream>
#include <map>

#include "fcl_mesh_peer.h"
#include "mtcs/io/cylinders_csv.h"
#include "mtcs/io/input_error.h"
#include "mtcs/mesh/bvh.h"
#include "mtcs/mesh/mesh_io.h"

namespace mtcs::bench {
namespace {

using Clock = std::chrono::steady_clock;

struct Sample {
  double us;
  double rel_err;
  bool wrong;
};

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0;
  const std::size_t k = std::min(v.size() - 1, std::size_t(q * double(v.size() - 1) + 0.5));
  std::nth_element(v.begin(), v.begin() + long(k), v.end());
  return v[k];
}

template <class F>
double median_ms(int runs, F&& f) {
  std::vector<double> ms;
  for (int i = 0; i < runs; ++i) {
    const auto t0 = Clock::now();
    f();
    ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
  }
  return quantile(ms, 0.5);
}

// One answer against the certified interval. `bounded` claims only "distance >= upper".
Sample judge(const io::NamedCylinder& c, double v, bool bounded, double upper, double scale, double us) {
  const double lo = *c.dist_lo, hi = *c.dist_hi;
  if (bounded) return {us, std::max(0.0, upper - hi) / scale, hi < upper};
  v = std::max(0.0, v);
  const double err = std::max({0.0, lo - v, v - hi});
  return {us, err / scale, (v == 0) != (hi == 0)};
}

}  // namespace

int bench_clearance(const std::vector<std::string>& meshes, const std::vector<std::string>& cases, int repeat,
                    int builds, double bound_fraction) {
  if (meshes.size() != cases.size()) throw std::runtime_error("give one --cases file per --mesh");
  std::cout.precision(4);
  std::cout << "mesh,triangles,method,upper_bound,build_ms,category,n,median_us,p90_us,max_rel_err,wrong_verdicts\n";
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    const auto part = mesh::read_mesh(meshes[m]);
    const auto rows = io::read_cylinders_csv(cases[m]);
    for (const auto& c : rows)
      if (!c.dist_lo || !c.dist_hi) throw io::InputError(cases[m], c.line, 1, "dist_lo", "certified interval needed");
    const double diagonal = part.bounds().size().norm(), extent = part.bounds().size().maxCoeff();
    const double upper = bound_fraction * extent;

    const double ours_build = median_ms(builds, [&] { const mesh::TriangleBvh b(part); });
    const double median_build = median_ms(builds, [&] { const mesh::TriangleBvh b(part, mesh::TriangleBvh::SplitRule::Median); });
    const double fcl_build = median_ms(builds, [&] { const FclMesh f(part); });
    const mesh::TriangleBvh bvh(part);
    const mesh::TriangleBvh bvh_median(part, mesh::TriangleBvh::SplitRule::Median);
    const FclMesh fcl(part);

    using Query = std::function<std::pair<double, bool>(const geometry::Cylinder&)>;
    const std::vector<std::tuple<std::string, double, double, Query>> methods{
        {"ours", std::numeric_limits<double>::infinity(), ours_build,
         [&](const geometry::Cylinder& c) {
           const auto r = mesh::cylinder_clearance(bvh, c);
           return std::pair{r.distance, r.bounded};
         }},
        {"ours-bounded", upper, ours_build,
         [&](const geometry::Cylinder& c) {
           const auto r = mesh::cylinder_clearance(bvh, c, upper);
           return std::pair{r.distance, r.bounded};
         }},
        {"ours-median-split", std::numeric_limits<double>::infinity(), median_build,
         [&](const geometry::Cylinder& c) {
           const auto r = mesh::cylinder_clearance(bvh_median, c);
           return std::pair{r.distance, r.bounded};
         }},
        {"fcl", std::numeric_limits<double>::infinity(), fcl_build,
         [&](const geometry::Cylinder& c) { return std::pair{fcl.distance(c), false}; }},
    };
    const std::string name = meshes[m].substr(meshes[m].find_last_of('/') + 1);
    for (const auto& [method, bound, build, query] : methods) {
      std::map<std::string, std::vector<Sample>> by_category;
      for (const auto& c : rows) {
        std::pair<double, bool> r{};
        volatile double sink = 0;
        const auto t0 = Clock::now();
        for (int k = 0; k < repeat; ++k) {
          r = query(c.cylinder);
          sink = sink + r.first;
        }
        const double us = std::chrono::duration<double, std::micro>(Clock::now() - t0).count() / repeat;
        const double scale = std::max({1.0, (c.cylinder.p1 - c.cylinder.p0).norm(), c.cylinder.radius, diagonal});
        const Sample s = judge(c, r.first, r.second, bound, scale, us);
        by_category[c.category].push_back(s);
        by_category["all"].push_back(s);
      }
      for (const auto& [category, samples] : by_category) {
        std::vector<double> us;
        double worst = 0;
        int wrong = 0;
        for (const Sample& s : samples) us.push_back(s.us), worst = std::max(worst, s.rel_err), wrong += s.wrong;
        std::cout << name << ',' << part.triangles.size() << ',' << method << ',' << bound << ',' << build << ','
                  << category << ',' << samples.size() << ',' << quantile(us, 0.5) << ',' << quantile(us, 0.9) << ','
                  << worst << ',' << wrong << '\n';
      }
    }
  }
  return 0;
}

}  // namespace mtcs::bench
