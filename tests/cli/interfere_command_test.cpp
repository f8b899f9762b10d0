// mtcs interfere end to end: the certified homer/gear placements (exact pair count, certified
// gap), JSON and text output, the coloured PLY, touching plates, and bad input (exit 2).

#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include <unistd.h>

#include "mtcs/mesh/mesh_io.h"
#include "support/scratch_file.h"
#include "support/paths.h"

namespace fs = std::filesystem;
using namespace mtcs;

namespace {

fs::path scratch(const std::string& name) {
  return mtcs_test::scratch_dir("interfere_cli") / name;
}

int run(const std::string& args, std::string* out) {
  const fs::path o = scratch("stdout");
  const int status = std::system((std::string(MTCS_BINARY) + " " + args + " >" + o.string() + " 2>&1").c_str());
  std::ifstream in(o);
  std::stringstream ss;
  ss << in.rdbuf();
  *out = ss.str();
  return WEXITSTATUS(status);
}

const std::string kMeshes = MTCS_TEST_DATA + "/meshes/";
// Rows of mesh_interference.csv: homer against the gear, 16 pairs at the overlap placement,
// [0.0012250035083989301, 0.0012250035083989307] apart at the gap placement.
const std::string kOverlap = " --translate 29.132630030337086,0.029399999999998983,-1.0000930000000001";
const std::string kGap = " --translate 29.152630030337086,0.029399999999998983,-1.0000930000000001";

}  // namespace

TEST_CASE("mtcs interfere: JSON pairs and distance at the certified placements", "[cli][interfere]") {
  std::string out;
  REQUIRE(run("interfere " + kMeshes + "homer.off " + kMeshes + "mcad_herringbone_gear.off" + kOverlap + " --json", &out) == 0);
  auto j = nlohmann::json::parse(out);
  CHECK(j["pairs"].size() == 16);
  CHECK(j["interferes"] == true);
  CHECK(j["distance"] == 0.0);
  int grouped = 0;
  for (const auto& g : j["groups"]) grouped += g["pairs"].get<int>();
  CHECK(grouped == 16);
  for (const auto& g : j["groups"]) {  // where each face is: on its mesh, with an area
    CHECK(g["area_a"].get<double>() > 0);
    CHECK(g["area_b"].get<double>() > 0);
    CHECK(g["centroid_a"].size() == 3);
    CHECK(g["centroid_b"].size() == 3);
  }
  CHECK(j["pairs"][0]["segment"].size() == 2);

  REQUIRE(run("interfere " + kMeshes + "homer.off " + kMeshes + "mcad_herringbone_gear.off" + kGap + " --json", &out) == 0);
  j = nlohmann::json::parse(out);
  CHECK(j["pairs"].empty());
  CHECK(j["interferes"] == false);
  const double d = j["distance"];
  CHECK(d >= 0.0012250035083989301 - 1e-9 * 106.739);
  CHECK(d <= 0.0012250035083989307 + 1e-9 * 106.739);
}

TEST_CASE("mtcs interfere: text report and the coloured PLY", "[cli][interfere]") {
  const fs::path ply = scratch("report.ply");
  std::string out;
  REQUIRE(run("interfere " + kMeshes + "homer.off " + kMeshes + "mcad_herringbone_gear.off" + kOverlap + " --out " + ply.string(), &out) == 0);
  CHECK(out.find("verdict: INTERFERENCE") != std::string::npos);
  CHECK(out.find("intersecting triangle pairs: 16") != std::string::npos);
  CHECK(out.find("pairs per face") != std::string::npos);
  const auto both = mesh::read_mesh(ply.string());
  CHECK(both.triangles.size() == 9856 + 11416);
  // Red faces: the triangles in interfering pairs (each line: 3 i j k r g b quality).
  std::ifstream in(ply);
  std::string line;
  int red = 0;
  while (std::getline(in, line)) red += line.rfind("3 ", 0) == 0 && line.find(" 220 30 30 2") != std::string::npos;
  CHECK(red > 0);
  CHECK(red <= 32);
}

TEST_CASE("mtcs interfere: plates face to face are contact, not interference", "[cli][interfere]") {
  const fs::path a = scratch("lower.stl"), b = scratch("upper.stl");
  mesh::write_stl(a.string(), mesh::box_mesh({{0, 0, 0}, {2, 2, 1}}));
  mesh::write_stl(b.string(), mesh::box_mesh({{0.5, 0.5, 0}, {1.5, 1.5, 1}}));
  std::string out;
  REQUIRE(run("interfere " + a.string() + " " + b.string() + " --translate 0,0,1", &out) == 0);
  CHECK(out.find("verdict: contact only") != std::string::npos);
  REQUIRE(run("interfere " + a.string() + " " + b.string() + " --translate 0,0,0.9 --touch-tolerance 0.05", &out) == 0);
  CHECK(out.find("verdict: INTERFERENCE") != std::string::npos);
  REQUIRE(run("interfere " + a.string() + " " + b.string() + " --translate 0,0,0.9 --touch-tolerance 0.2", &out) == 0);
  CHECK(out.find("verdict: contact only") != std::string::npos);
}

// Issue 45: the trial's 1 278 face-pair lines said nothing of how deep the parts overlap. A
// 12 x 6 x 6 mm block pushed 1.5 mm into a 10 mm cube (its corners 2 mm inside the cube's other
// faces): its deepest corner lies 1.5 mm inside, the closed form.
TEST_CASE("mtcs interfere: the overlap depth per face and overall is the closed form of two boxes", "[cli][interfere]") {
  const fs::path a = scratch("cube.stl"), b = scratch("bar.stl");
  mesh::write_stl(a.string(), mesh::box_mesh({{0, 0, 0}, {10, 10, 10}}));
  mesh::write_stl(b.string(), mesh::box_mesh({{8.5, 2, 2}, {20.5, 8, 8}}));
  std::string out;
  REQUIRE(run("interfere " + a.string() + " " + b.string() + " --json", &out) == 0);
  const auto j = nlohmann::json::parse(out);
  CHECK(j["overlap_depth"].get<double>() == Approx(1.5).margin(1e-12));
  double deepest = 0;
  for (const auto& g : j["groups"]) {
    CHECK(g["depth"].get<double>() <= 1.5 + 1e-12);
    deepest = std::max(deepest, g["depth"].get<double>());
  }
  CHECK(deepest == Approx(1.5).margin(1e-12));
  REQUIRE(run("interfere " + a.string() + " " + b.string(), &out) == 0);
  CHECK(out.find("overlap depth: 1.5 (the deepest vertex") != std::string::npos);
  // Apart: no pairs, no depth.
  REQUIRE(run("interfere " + a.string() + " " + b.string() + " --translate 5,0,0 --json", &out) == 0);
  CHECK(nlohmann::json::parse(out)["overlap_depth"].is_null());
}

TEST_CASE("mtcs interfere: bad input exits 2 naming the file and the reason", "[cli][interfere]") {
  std::string out;
  CHECK(run("interfere " + scratch("missing.stl").string() + " " + kMeshes + "homer.off", &out) == 2);
  CHECK(out.find("missing.stl") != std::string::npos);
  // An open box (one triangle removed).
  auto open = mesh::box_mesh({{0, 0, 0}, {1, 1, 1}});
  open.triangles.pop_back();
  const fs::path holed = scratch("holed.stl");
  mesh::write_stl(holed.string(), open);
  CHECK(run("interfere " + kMeshes + "homer.off " + holed.string(), &out) == 2);
  CHECK(out.find("holed.stl") != std::string::npos);
  CHECK(out.find("not closed") != std::string::npos);
  // Closed and oriented, but two boxes through each other: self-intersecting.
  auto crossed = mesh::box_mesh({{0, 0, 0}, {2, 2, 2}});
  const auto second = mesh::box_mesh({{1, 1, 1}, {3, 3, 3}});
  for (const auto& v : second.vertices) crossed.vertices.push_back(v);
  for (auto t : second.triangles) crossed.triangles.push_back({t[0] + 8, t[1] + 8, t[2] + 8});
  const fs::path self = scratch("crossed.stl");
  mesh::write_stl(self.string(), crossed);
  CHECK(run("interfere " + self.string() + " " + kMeshes + "homer.off", &out) == 2);
  CHECK(out.find("crossed.stl") != std::string::npos);
  CHECK(out.find("intersect each other") != std::string::npos);
  CHECK(run("interfere " + kMeshes + "homer.off " + kMeshes + "homer.off --translate 1,2", &out) == 2);
  CHECK(run("interfere --help", &out) == 0);
  CHECK(out.find("Examples") != std::string::npos);
}

TEST_CASE("mtcs bench interfere: ours, FCL and CGAL agree on the homer/gear placements", "[cli][interfere]") {
  const fs::path cases = scratch("cases.csv");
  std::ofstream(cases) << "mesh_a,mesh_b,tx,ty,tz,pairs,distance_lo,distance_hi\n"
                          "homer,mcad_herringbone_gear,29.132630030337086,0.029399999999998983,-1.0000930000000001,16,-1,-1\n"
                          "homer,mcad_herringbone_gear,29.152630030337086,0.029399999999998983,-1.0000930000000001,-1,"
                          "0.0012250035083989301,0.0012250035083989307\n";
  std::string out;
  REQUIRE(run("bench interfere --repeat 1 --cases " + cases.string() + " --meshes " + MTCS_TEST_DATA + "/meshes", &out) == 0);
  std::istringstream lines(out);
  std::string header, line;
  std::getline(lines, header);
  std::vector<std::string> names;
  {
    std::stringstream ss(header);
    for (std::string f; std::getline(ss, f, ',');) names.push_back(f);
  }
  int rows = 0;
  while (std::getline(lines, line)) {
    std::stringstream ss(line);
    std::map<std::string, std::string> row;
    for (std::size_t i = 0; i < names.size(); ++i) std::getline(ss, row[names[i]], ',');
    const bool overlap = row["kind"] == "overlap";
    CHECK(row["ours_pairs"] == (overlap ? "16" : "0"));
    CHECK(row["ours_face_pairs"] == row["ours_pairs"]);
    CHECK(row["fcl_pairs"] == row["ours_pairs"]);
    CHECK(row["fcl_same_pairs"] == "1");
    CHECK(row["cgal_intersect"] == (overlap ? "1" : "0"));
    CHECK(row["distance_ok"] == "1");
    ++rows;
  }
  CHECK(rows == 2);
}
