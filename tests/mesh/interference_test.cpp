// Mesh-vs-mesh interference against independent references: the certified placements of
// shared/cases/mesh_interference.csv (exact pair counts from CGAL's exact predicates, certified
// gap intervals), brute force over all triangle pairs, CGAL's PMP::do_intersect verdicts, and
// closed forms on boxes (touching plates, pushed-in plates, nested boxes, gaps).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/intersection.h>
#include <CGAL/Surface_mesh.h>

#include <catch2/catch.hpp>
#include <fstream>
#include <map>
#include <random>
#include <sstream>

#include "mtcs/mesh/interference.h"
#include "mtcs/mesh/interference_view.h"
#include "mtcs/mesh/mesh_io.h"
#include "support/paths.h"
#include "support/random_draws.h"

using namespace mtcs;
using geometry::Vec3;
using mesh::InterferenceBvh;
using mesh::TriangleMesh;

namespace {

TriangleMesh load(const std::string& name) { return mesh::read_mesh(MTCS_TEST_DATA + "/meshes/" + name + ".off"); }

const TriangleMesh& cached(const std::string& name) {
  static std::map<std::string, TriangleMesh> meshes;
  auto it = meshes.find(name);
  if (it == meshes.end()) it = meshes.emplace(name, load(name)).first;
  return it->second;
}

TriangleMesh moved(TriangleMesh m, const Vec3& t) {
  m.translate(t);
  return m;
}

InterferenceBvh bvh(const TriangleMesh& m, InterferenceBvh::Split split = InterferenceBvh::Split::kMedian) {
  return InterferenceBvh(m, mesh::split_parts(m), split);
}

TriangleMesh merged(const TriangleMesh& a, const TriangleMesh& b) {
  TriangleMesh m = a;
  const int off = int(a.vertices.size());
  m.vertices.insert(m.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (auto t : b.triangles) m.triangles.push_back({t[0] + off, t[1] + off, t[2] + off});
  return m;
}

struct Placement {
  std::string a, b;
  Vec3 t;
  long pairs;
  double lo, hi;
};

std::vector<Placement> placements() {
  std::ifstream in(MTCS_TEST_DATA + "/mesh_interference.csv");
  std::string line;
  std::getline(in, line);
  std::vector<Placement> rows;
  while (std::getline(in, line)) {
    std::stringstream ss(line);
    std::string f[8];
    for (auto& x : f) std::getline(ss, x, ',');
    rows.push_back({f[0], f[1], Vec3(std::stod(f[2]), std::stod(f[3]), std::stod(f[4])), std::stol(f[5]),
                    std::stod(f[6]), std::stod(f[7])});
  }
  return rows;
}

double diagonal(const TriangleMesh& a, const TriangleMesh& b) {
  const auto ba = a.bounds(), bb = b.bounds();
  return (ba.max.cwiseMax(bb.max) - ba.min.cwiseMin(bb.min)).norm();
}

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<K::Point_3>;

SurfaceMesh to_cgal(const TriangleMesh& m) {
  SurfaceMesh s;
  std::vector<SurfaceMesh::Vertex_index> v;
  for (const Vec3& p : m.vertices) v.push_back(s.add_vertex(K::Point_3(p.x(), p.y(), p.z())));
  for (const auto& t : m.triangles) s.add_face(v[std::size_t(t[0])], v[std::size_t(t[1])], v[std::size_t(t[2])]);
  return s;
}

}  // namespace

TEST_CASE("interference: certified placements (exact pair counts, gap intervals)", "[mesh][interference]") {
  const auto rows = placements();
  REQUIRE(rows.size() == 12);
  for (const auto& row : rows) {
    INFO(row.a << " vs " << row.b << " at " << row.t.transpose());
    const TriangleMesh& a = cached(row.a);
    const TriangleMesh b = moved(cached(row.b), row.t);
    for (auto split : {InterferenceBvh::Split::kMedian, InterferenceBvh::Split::kSolidFace}) {
      const auto r = mesh::interfere(a, b, 0, split);
      if (row.pairs >= 0) {
        CHECK(long(r.pairs.size()) == row.pairs);
        CHECK(r.interferes);
        CHECK(r.distance == 0);
      } else {
        const double tol = 1e-9 * std::max(1.0, diagonal(a, b));
        CHECK(r.pairs.empty());
        CHECK_FALSE(r.interferes);
        CHECK(r.distance >= row.lo - tol);
        CHECK(r.distance <= row.hi + tol);
      }
    }
  }
}

TEST_CASE("interference: the pairs equal brute force over all triangle pairs", "[mesh][interference]") {
  // homer against the gear at the certified overlap placement, and pushed further in.
  const TriangleMesh& a = cached("homer");
  for (double extra : {0.0, 0.05, 0.2}) {
    const TriangleMesh b = moved(cached("mcad_herringbone_gear"), Vec3(29.132630030337086 - extra, 0.029399999999998983, -1.0000930000000001));
    std::vector<std::pair<int, int>> brute;
    std::vector<geometry::Box> boxes_b;
    for (std::size_t j = 0; j < b.triangles.size(); ++j) {
      const mesh::Triangle tb{b.corner(j, 0), b.corner(j, 1), b.corner(j, 2)};
      boxes_b.push_back({tb[0].cwiseMin(tb[1]).cwiseMin(tb[2]), tb[0].cwiseMax(tb[1]).cwiseMax(tb[2])});
    }
    for (std::size_t i = 0; i < a.triangles.size(); ++i) {
      const mesh::Triangle ta{a.corner(i, 0), a.corner(i, 1), a.corner(i, 2)};
      const Vec3 lo = ta[0].cwiseMin(ta[1]).cwiseMin(ta[2]), hi = ta[0].cwiseMax(ta[1]).cwiseMax(ta[2]);
      for (std::size_t j = 0; j < b.triangles.size(); ++j) {
        if ((lo.array() > boxes_b[j].max.array()).any() || (boxes_b[j].min.array() > hi.array()).any()) continue;
        if (mesh::triangles_intersect(ta, {b.corner(j, 0), b.corner(j, 1), b.corner(j, 2)})) brute.emplace_back(int(i), int(j));
      }
    }
    const auto pairs = mesh::intersecting_pairs(bvh(a), bvh(b));
    std::vector<std::pair<int, int>> ours;
    for (const auto& p : pairs) ours.emplace_back(p.a, p.b);
    CHECK(ours == brute);
    CHECK(!brute.empty());
  }
}

TEST_CASE("interference: verdicts equal CGAL's PMP::do_intersect on random placements", "[mesh][interference]") {
  const TriangleMesh& a = cached("homer");
  const TriangleMesh& b0 = cached("turbine");
  const SurfaceMesh ca = to_cgal(a);
  const InterferenceBvh ba = bvh(a);
  std::mt19937_64 rng(6);
  std::uniform_real_distribution<double> u(-0.6, 0.6);
  int hits = 0;
  for (int i = 0; i < 30; ++i) {
    const TriangleMesh b = moved(b0, mtcs_test::draw_vec3(u, rng));
    const bool want = CGAL::Polygon_mesh_processing::do_intersect(ca, to_cgal(b));
    const auto pairs = mesh::intersecting_pairs(ba, bvh(b));
    CHECK(!pairs.empty() == want);
    hits += want;
  }
  CHECK(hits > 5);
  CHECK(hits < 25);
}

TEST_CASE("interference: plates touching face to face are not interference, pushed in, they are", "[mesh][interference]") {
  const auto a = mesh::box_mesh({{0, 0, 0}, {2, 2, 1}});
  for (const Vec3& shift : {Vec3(0, 0, 0), Vec3(0.3, 0.7, 0)}) {
    // Face to face: the pairs are touches only, the distance 0. Without a tolerance every
    // contact counts, as in FCL and CGAL.
    const auto upper = mesh::box_mesh({Vec3(0, 0, 1) + shift, Vec3(2, 2, 2) + shift});
    const auto touching = mesh::interfere(a, upper, 1e-9);
    CHECK(!touching.pairs.empty());
    CHECK(touching.penetrating == 0);
    CHECK_FALSE(touching.interferes);
    CHECK(touching.distance == 0);
    CHECK(mesh::interfere(a, upper, 0).interferes);
    // Pushed 0.01 into the lower plate: interference beyond a tolerance below 0.01, not above.
    const auto pushed = mesh::box_mesh({Vec3(0, 0, 0.99) + shift, Vec3(2, 2, 2) + shift});
    const auto deep = mesh::interfere(a, pushed, 0.0099);
    CHECK(deep.interferes);
    CHECK(deep.penetrating > 0);
    CHECK_FALSE(mesh::interfere(a, pushed, 0.0101).interferes);
  }
  // Apart by 0.25 above: the gap is the distance.
  const auto apart = mesh::interfere(a, mesh::box_mesh({{0.5, 0.5, 1.25}, {1, 1, 2}}), 0);
  CHECK(apart.pairs.empty());
  CHECK(apart.distance == Approx(0.25).epsilon(1e-14));
  // Corner to corner across a diagonal gap (0.1, 0.2, 0.2): the distance 0.3.
  const auto diag = mesh::interfere(a, mesh::box_mesh({{2.1, 2.2, 1.2}, {3, 3, 3}}), 0);
  CHECK(diag.distance == Approx(0.3).epsilon(1e-14));
}

TEST_CASE("interference: shrinking moves every face of a box by the offset", "[mesh][interference]") {
  const auto s = mesh::shrunk(mesh::box_mesh({{0, 0, 0}, {2, 3, 4}}), 0.25);
  const auto b = s.bounds();
  CHECK((b.min - Vec3(0.25, 0.25, 0.25)).norm() < 1e-15);
  CHECK((b.max - Vec3(1.75, 2.75, 3.75)).norm() < 1e-15);
}

TEST_CASE("interference: nested components are interference without touching surfaces", "[mesh][interference]") {
  const auto outer = mesh::box_mesh({{0, 0, 0}, {10, 10, 10}});
  const auto inner = mesh::box_mesh({{2, 3, 4}, {5, 6, 7}});
  for (double tol : {0.0, 1e-6}) {
    const auto in = mesh::interfere(outer, inner, tol);
    CHECK(in.pairs.empty());
    CHECK(in.interferes);
    CHECK(in.solids_of_b_inside_a == std::vector<int>{0});
    CHECK(in.solids_of_a_inside_b.empty());
    const auto out = mesh::interfere(inner, outer, tol);
    CHECK(out.solids_of_a_inside_b == std::vector<int>{0});
    // Two solids in B: one inside A, one outside; solids are numbered in mesh order.
    const auto two = merged(mesh::box_mesh({{20, 0, 0}, {21, 1, 1}}), inner);
    const auto r = mesh::interfere(outer, two, tol);
    CHECK(r.solids_of_b_inside_a == std::vector<int>{1});
    // Touching the inner wall face to face from inside is still interference.
    CHECK(mesh::interfere(outer, mesh::box_mesh({{0, 3, 4}, {5, 6, 7}}), tol).interferes);
  }
}
TEST_CASE("parts: solids are connected components, faces near-planar patches", "[mesh][interference]") {
  const auto two = merged(mesh::box_mesh({{0, 0, 0}, {1, 1, 1}}), mesh::box_mesh({{3, 0, 0}, {4, 1, 1}}));
  const auto parts = mesh::split_parts(two);
  CHECK(parts.solids == 2);
  CHECK(parts.faces() == 12);
  for (std::size_t t = 0; t < two.triangles.size(); ++t) CHECK(parts.solid_of[t] == int(t / 12));
  // The gear's planar sides are single faces; every face stays in one solid.
  const auto& gear = cached("mcad_herringbone_gear");
  const auto gp = mesh::split_parts(gear);
  CHECK(gp.solids == 1);
  CHECK(gp.faces() > 10);
  CHECK(gp.faces() < int(gear.triangles.size()) / 4);
}

TEST_CASE("parts: a face's shape is where its triangles are (centroid, area)", "[mesh][interference]") {
  // A 3 x 2 x 1 box: six faces, each centred on its side with the side's area.
  const auto box = mesh::box_mesh({{0, 0, 0}, {3, 2, 1}});
  const auto parts = mesh::split_parts(box);
  const auto shapes = mesh::face_shapes(box, parts);
  REQUIRE(shapes.size() == 6);
  double total = 0;
  for (const auto& s : shapes) {
    total += s.area;
    const Vec3 c = s.centroid;
    const int on_side = int(std::abs(c.x()) < 1e-12 || std::abs(c.x() - 3) < 1e-12) +
                        int(std::abs(c.y()) < 1e-12 || std::abs(c.y() - 2) < 1e-12) +
                        int(std::abs(c.z()) < 1e-12 || std::abs(c.z() - 1) < 1e-12);
    CHECK(on_side == 1);  // on exactly one side, in its middle
    if (std::abs(c.x()) < 1e-12 || std::abs(c.x() - 3) < 1e-12) CHECK(s.area == Approx(2.0));
    if (std::abs(c.z()) < 1e-12 || std::abs(c.z() - 1) < 1e-12) CHECK(s.area == Approx(6.0));
  }
  CHECK(total == Approx(2 * (6 + 3 + 2)));
  // On a curved mesh the faces' areas add up to the surface's.
  const auto& gear = cached("mcad_herringbone_gear");
  double sum = 0;
  for (const auto& s : mesh::face_shapes(gear, mesh::split_parts(gear))) sum += s.area;
  CHECK(sum == Approx(gear.area()).epsilon(1e-12));
}

TEST_CASE("self-intersections: none in the shipped meshes, found in overlapping boxes", "[mesh][interference]") {
  CHECK(mesh::self_intersections(bvh(cached("homer"))).empty());
  const auto two = merged(mesh::box_mesh({{0, 0, 0}, {2, 2, 2}}), mesh::box_mesh({{1, 1, 1}, {3, 3, 3}}));
  const auto found = mesh::self_intersections(bvh(two));
  // The same pairs as brute force over all non-adjacent pairs.
  std::vector<std::array<int, 2>> brute;
  for (int i = 0; i < 24; ++i)
    for (int j = i + 1; j < 24; ++j) {
      bool adjacent = false;
      for (int p : two.triangles[i])
        for (int q : two.triangles[j]) adjacent |= p == q;
      if (!adjacent && mesh::triangles_intersect({two.corner(i, 0), two.corner(i, 1), two.corner(i, 2)},
                                                 {two.corner(j, 0), two.corner(j, 1), two.corner(j, 2)}))
        brute.push_back({i, j});
    }
  CHECK(found == brute);
  CHECK(!found.empty());
}

TEST_CASE("interference: surface distance equals brute force over all triangle pairs", "[mesh][interference]") {
  // A large, rotated box (big triangles, so the pruning by planes and edge planes matters)
  // around and beside homer, and homer against a small box: distances against the minimum of
  // triangle_distance over all pairs.
  const TriangleMesh& homer = cached("homer");
  const InterferenceBvh bh = bvh(homer);
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(-1, 1);
  int apart = 0;
  for (int i = 0; i < 12; ++i) {
    const double size = i % 2 ? 3.0 : 0.05;
    TriangleMesh box = mesh::box_mesh({{0, 0, 0}, {size, size * 0.7, size * 0.4}});
    const Eigen::Matrix3d r = mtcs_test::draw_quaternion(u, rng).normalized().toRotationMatrix();
    const Vec3 at = homer.bounds().max + mtcs_test::draw_vec3(u, rng) * 0.6;
    for (Vec3& v : box.vertices) v = r * v + at;
    double brute = std::numeric_limits<double>::infinity();
    for (std::size_t a = 0; a < homer.triangles.size(); ++a)
      for (std::size_t b = 0; b < box.triangles.size(); ++b)
        brute = std::min(brute, mesh::triangle_distance({homer.corner(a, 0), homer.corner(a, 1), homer.corner(a, 2)},
                                                        {box.corner(b, 0), box.corner(b, 1), box.corner(b, 2)}));
    CHECK(mesh::surface_distance(bh, bvh(box)) == Approx(brute).epsilon(1e-12).margin(1e-15));
    CHECK(mesh::surface_distance(bvh(box), bh) == Approx(brute).epsilon(1e-12).margin(1e-15));
    apart += brute > 0;
  }
  CHECK(apart >= 4);
}
