#include "mtcs/mesh/interference_report.h"

#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <nlohmann/json.hpp>

namespace mtcs::mesh {
namespace {

// printf into a stream (the report's number formats are printf's).
__attribute__((format(printf, 2, 3))) void print(std::ostream& out, const char* format, ...) {
  va_list args, again;
  va_start(args, format);
  va_copy(again, args);
  const int n = std::vsnprintf(nullptr, 0, format, args);
  va_end(args);
  std::string text(std::size_t(n) + 1, '\0');
  std::vsnprintf(text.data(), text.size(), format, again);
  va_end(again);
  text.pop_back();
  out << text;
}

}  // namespace

void write_interference_json(std::ostream& out, const InterferenceCheck& what, const TriangleMesh& a,
                             const TriangleMesh& b, const InterferenceReport& report, const MeshParts& pa,
                             const MeshParts& pb, const std::vector<FaceGroup>& groups) {
  auto point = [](const geometry::Vec3& v) { return nlohmann::json::array({v.x(), v.y(), v.z()}); };
  nlohmann::json j;
  j["a"] = what.a, j["b"] = what.b, j["translate"] = what.translate;
  j["touch_tolerance"] = what.tolerance;
  j["interferes"] = report.interferes;
  j["distance"] = report.distance;
  j["pair_count"] = report.pairs.size();
  j["penetrating_pairs"] = report.penetrating;
  j["solids_of_a_inside_b"] = report.solids_of_a_inside_b;
  j["solids_of_b_inside_a"] = report.solids_of_b_inside_a;
  j["pairs"] = nlohmann::json::array();
  for (const auto& p : report.pairs)
    j["pairs"].push_back({{"a", p.a},
                          {"b", p.b},
                          {"solid_a", pa.solid_of[std::size_t(p.a)]},
                          {"face_a", pa.face_of[std::size_t(p.a)]},
                          {"solid_b", pb.solid_of[std::size_t(p.b)]},
                          {"face_b", pb.face_of[std::size_t(p.b)]},
                          {"penetrating", p.penetrating},
                          {"coplanar", p.x.coplanar},
                          {"segment", {point(p.x.p), point(p.x.q)}}});
  double depth = 0;
  for (const auto& g : groups) depth = std::max(depth, g.depth);
  // The deepest vertex of an intersecting triangle inside the other solid; null without such
  // pairs (apart, or one solid wholly inside the other: see the nesting).
  j["overlap_depth"] = report.pairs.empty() ? nlohmann::json() : nlohmann::json(depth);
  j["groups"] = nlohmann::json::array();
  const std::vector<FaceShape> shapes_a = groups.empty() ? std::vector<FaceShape>{} : face_shapes(a, pa);
  const std::vector<FaceShape> shapes_b = groups.empty() ? std::vector<FaceShape>{} : face_shapes(b, pb);
  for (const auto& g : groups) {
    const FaceShape& fa = shapes_a[std::size_t(g.face_a)];
    const FaceShape& fb = shapes_b[std::size_t(g.face_b)];
    j["groups"].push_back({{"solid_a", g.solid_a},
                           {"face_a", g.face_a},
                           {"solid_b", g.solid_b},
                           {"face_b", g.face_b},
                           {"pairs", g.pairs},
                           {"penetrating", g.penetrating},
                           {"depth", g.depth},
                           {"centroid_a", point(fa.centroid)},
                           {"area_a", fa.area},
                           {"centroid_b", point(fb.centroid)},
                           {"area_b", fb.area}});
  }
  out << j.dump(1) << '\n';
}

void write_interference_text(std::ostream& out, const InterferenceCheck& what, const TriangleMesh& a,
                             const TriangleMesh& b, const InterferenceReport& report, const MeshParts& pa,
                             const MeshParts& pb, const std::vector<FaceGroup>& groups) {
  print(out, "A: %s (%zu triangles, %d solid(s), %d faces)\nB: %s (%zu triangles, %d solid(s), %d faces)\n",
        what.a.c_str(), a.triangles.size(), pa.solids, pa.faces(), what.b.c_str(), b.triangles.size(),
        pb.solids, pb.faces());
  print(out, "verdict: %s\n",
        report.interferes      ? "INTERFERENCE"
        : report.pairs.empty() ? "apart"
                               : "contact only");
  print(out, "intersecting triangle pairs: %zu (beyond the touch tolerance %.3g: %zu)\n", report.pairs.size(),
        what.tolerance, report.penetrating);
  for (int s : report.solids_of_a_inside_b) print(out, "solid %d of A lies inside B\n", s);
  for (int s : report.solids_of_b_inside_a) print(out, "solid %d of B lies inside A\n", s);
  if (report.pairs.empty() && !report.interferes) print(out, "distance: %.17g\n", report.distance);
  double depth = 0;
  for (const auto& g : groups) depth = std::max(depth, g.depth);
  if (!groups.empty())
    print(out, "overlap depth: %.6g (the deepest vertex of an intersecting triangle inside the other solid)\n"
               "pairs per face (solid.face of A x solid.face of B: pairs, interfering, overlap depth):\n", depth);
  for (const auto& g : groups)
    print(out, "  A %d.%d x B %d.%d: %d, %d, %.6g\n", g.solid_a, g.face_a, g.solid_b, g.face_b, g.pairs,
          g.penetrating, g.depth);
  if (!report.pairs.empty()) print(out, "pairs (triangle of A, triangle of B, interfering, segment):\n");
  for (const auto& p : report.pairs)
    print(out, "  %d %d %d  %.9g %.9g %.9g  %.9g %.9g %.9g\n", p.a, p.b, int(p.penetrating), p.x.p.x(),
          p.x.p.y(), p.x.p.z(), p.x.q.x(), p.x.q.y(), p.x.q.z());
}

}  // namespace mtcs::mesh
