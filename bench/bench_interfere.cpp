// mtcs bench interfere: all intersecting triangle pairs of two placed meshes, ours (both
// hierarchy splits) against FCL 0.7's all-contacts collide (BVHModel<OBBRSS>) and CGAL 5.5's
// PMP::do_intersect, in the same run on the same doubles; pair counts against the exact ones of
// the cases file, distances at gap placements against the certified intervals.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <vector>

#include "bench_interfere.h"
#include "cgal_interference_peer.h"
#include "fcl_mesh_peer.h"
#include "mtcs/io/input_error.h"
#include "mtcs/mesh/interference.h"
#include "mtcs/mesh/mesh_io.h"

namespace mtcs::bench {
namespace {

using mesh::InterferenceBvh;

// Median milliseconds of `repeat` calls (at least one).
template <class F>
double median_ms(int repeat, F&& f) {
  std::vector<double> t;
  for (int i = 0; i < std::max(1, repeat); ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    t.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  std::nth_element(t.begin(), t.begin() + long(t.size() / 2), t.end());
  return t[t.size() / 2];
}

struct Row {
  std::string a, b;
  geometry::Vec3 t;
  long pairs;
  double lo, hi;
};

std::vector<Row> read_cases(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw io::InputError(path, 0, 0, "", "cannot open the cases file");
  std::string line;
  std::getline(in, line);
  std::vector<Row> rows;
  for (int n = 2; std::getline(in, line); ++n) {
    std::stringstream ss(line);
    std::string f[8];
    for (auto& x : f) std::getline(ss, x, ',');
    try {
      rows.push_back({f[0], f[1], {std::stod(f[2]), std::stod(f[3]), std::stod(f[4])}, std::stol(f[5]), std::stod(f[6]), std::stod(f[7])});
    } catch (const std::exception&) {
      throw io::InputError(path, n, 1, "", "expected mesh_a,mesh_b,tx,ty,tz,pairs,distance_lo,distance_hi");
    }
  }
  return rows;
}

}  // namespace

int bench_interfere(const std::string& cases, const std::string& meshes, int repeat) {
  std::map<std::string, mesh::TriangleMesh> loaded;
  auto load = [&](const std::string& name) -> const mesh::TriangleMesh& {
    auto it = loaded.find(name);
    if (it == loaded.end()) it = loaded.emplace(name, mesh::read_mesh(meshes + "/" + name + ".off")).first;
    return it->second;
  };
  std::printf(
      "mesh_a,mesh_b,kind,want_pairs,ours_pairs,ours_face_pairs,fcl_pairs,fcl_same_pairs,cgal_intersect,"
      "ours_build_ms,ours_face_build_ms,fcl_build_ms,ours_ms,ours_face_ms,fcl_ms,cgal_ms,fcl_over_ours,"
      "triangle_tests,face_triangle_tests,all_pairs,tested_share,node_pairs,distance,distance_ok,distance_ms,"
      "distance_node_pairs,distance_triangle_tests,fcl_distance,fcl_distance_ok,fcl_distance_ms\n");
  for (const Row& row : read_cases(cases)) {
    const mesh::TriangleMesh& a = load(row.a);
    mesh::TriangleMesh b = load(row.b);
    b.translate(row.t);  // fl(v + t), as the cases define it
    const auto pa = mesh::split_parts(a), pb = mesh::split_parts(b);

    std::optional<InterferenceBvh> ma, mb, fa, fb;
    const double build = median_ms(repeat, [&] { ma.emplace(a, pa), mb.emplace(b, pb); });
    const double face_build = median_ms(repeat, [&] {
      fa.emplace(a, pa, InterferenceBvh::Split::kSolidFace), fb.emplace(b, pb, InterferenceBvh::Split::kSolidFace);
    });
    std::optional<FclMesh> ca, cb;
    const double fcl_build = median_ms(repeat, [&] { ca.emplace(a), cb.emplace(b); });
    const CgalMesh ga(a), gb(b);

    std::vector<mesh::InterferencePair> ours, face;
    mesh::InterferenceStats stats, face_stats;
    std::vector<std::array<int, 2>> fcl;
    bool cgal = false;
    const double t_ours = median_ms(repeat, [&] { ours = mesh::intersecting_pairs(*ma, *mb, &stats); });
    const double t_face = median_ms(repeat, [&] { face = mesh::intersecting_pairs(*fa, *fb, &face_stats); });
    const double t_fcl = median_ms(repeat, [&] { fcl = fcl_colliding_pairs(*ca, *cb); });
    const double t_cgal = median_ms(repeat, [&] { cgal = cgal_do_intersect(ga, gb); });

    std::vector<std::array<int, 2>> ours_set;
    for (const auto& p : ours) ours_set.push_back({p.a, p.b});
    std::sort(fcl.begin(), fcl.end());
    const double all = double(a.triangles.size()) * double(b.triangles.size());
    double distance = -1, t_distance = 0;
    bool distance_ok = true;
    mesh::InterferenceStats distance_stats;
    double fcl_distance = -1, t_fcl_distance = 0;
    bool fcl_distance_ok = true;
    if (row.pairs < 0) {
      t_distance = median_ms(repeat, [&] { distance = mesh::surface_distance(*ma, *mb, &distance_stats); });
      const auto ba = a.bounds(), bb = b.bounds();
      const double tol = 1e-9 * std::max(1.0, (ba.max.cwiseMax(bb.max) - ba.min.cwiseMin(bb.min)).norm());
      distance_ok = distance >= row.lo - tol && distance <= row.hi + tol;
      t_fcl_distance = median_ms(repeat, [&] { fcl_distance = fcl_mesh_distance(*ca, *cb); });
      fcl_distance_ok = fcl_distance >= row.lo - tol && fcl_distance <= row.hi + tol;
    }
    std::printf("%s,%s,%s,%ld,%zu,%zu,%zu,%d,%d,%.4g,%.4g,%.4g,%.4g,%.4g,%.4g,%.4g,%.3g,%zu,%zu,%.0f,%.3g,%zu,%.17g,%d,%.4g,%zu,%zu,%.17g,%d,%.4g\n",
                row.a.c_str(), row.b.c_str(), row.pairs >= 0 ? "overlap" : "gap", row.pairs, ours.size(), face.size(),
                fcl.size(), int(fcl == ours_set), int(cgal), build, face_build, fcl_build, t_ours, t_face, t_fcl, t_cgal,
                t_fcl / t_ours, stats.triangle_tests, face_stats.triangle_tests, all, double(stats.triangle_tests) / all,
                stats.node_pairs, distance, int(distance_ok), t_distance, distance_stats.node_pairs, distance_stats.triangle_tests, fcl_distance,
                int(fcl_distance_ok), t_fcl_distance);
    std::fflush(stdout);
  }
  return 0;
}

}  // namespace mtcs::bench
