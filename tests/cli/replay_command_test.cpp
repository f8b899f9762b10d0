// mtcs replay's plots and CAD files: a PNG per replayed generation named so that the series
// sorts (when python3 has matplotlib), and per final front member an STL that our mesh reader
// reads back as a closed mesh holding exactly the volume of its bores (24-gon prisms).

#include <catch2/catch.hpp>
#include <cmath>
#include <nlohmann/json.hpp>

#include "mtcs/mesh/mesh_io.h"
#include "run_mtcs.h"
#include "support/paths.h"

using mtcs_test::has_matplotlib;
using mtcs_test::run_mtcs;
namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) { return mtcs_test::scratch("replay_cli", name); }

// Volume of the bores in a bores.csv, each a prism on a regular 24-gon of the bore's radius.
double prism_volume(const fs::path& bores_csv) {
  std::ifstream in(bores_csv);
  std::string line;
  std::getline(in, line);
  REQUIRE(line.rfind("name,circuit,segment,p0x,p0y,p0z,p1x,p1y,p1z,diameter", 0) == 0);
  double volume = 0;
  while (std::getline(in, line)) {
    std::stringstream ss(line);
    std::string cell;
    std::vector<double> v;
    for (int k = 0; std::getline(ss, cell, ',') && k < 10; ++k)
      if (k >= 3) v.push_back(std::stod(cell));
    const double length = std::hypot(v[3] - v[0], v[4] - v[1], v[5] - v[2]), r = v[6] / 2;
    volume += length * 0.5 * 24 * r * r * std::sin(2 * M_PI / 24);
  }
  return volume;
}

}  // namespace

TEST_CASE("mtcs replay writes a front plot per generation and an STL per final front member", "[cli][replay]") {
  const fs::path dir = scratch("run");
  fs::remove_all(dir);
  REQUIRE(run_mtcs("optimize " + MTCS_SOURCE_DIR + "/molds/plate_wall_distance.yaml --algorithm sms-emoa --evaluations 400 --seed 2 --config " + MTCS_TEST_DATA +
                   "/configs/no_reach.yaml --out " +
                   dir.string() + " --quiet") == 0);
  REQUIRE(run_mtcs("replay " + dir.string()) == 0);
  const fs::path replay = dir / "replay";
  std::ifstream in(replay / "frames.json");
  const auto frames = nlohmann::json::parse(in);
  CHECK(frames["objectives"].size() == 3);
  REQUIRE(frames["limits"].size() == 3);
  for (const auto& l : frames["limits"]) CHECK(l[0].get<double>() <= l[1].get<double>());
  // Stored every 10 steps (mu = 10) from 0 to 390: 40 frames, numbered by generation.
  REQUIRE(frames["frames"].size() == 40);
  CHECK(frames["frames"][1]["png"] == "front_0010.png");
  if (has_matplotlib()) {
    for (const auto& f : frames["frames"]) {
      std::ifstream png(replay / f["png"].get<std::string>(), std::ios::binary);
      char magic[8] = {};
      png.read(magic, 8);
      CHECK(std::string(magic + 1, 3) == "PNG");
    }
  }
  // The last front: each member's STL is closed and holds its bores' volume.
  std::ifstream last(replay / ("front_" + std::to_string(frames["frames"].back()["generation"].get<int>()) + ".json"));
  const auto front = nlohmann::json::parse(last);
  REQUIRE(!front["front"].empty());
  for (const auto& member : front["front"]) {
    const std::string stem = "front_" + std::to_string(front["generation"].get<int>()) + "_rank" +
                             std::to_string(member["rank"].get<int>());
    const auto mesh = mtcs::mesh::read_mesh((replay / (stem + ".bores.stl")).string());
    CHECK(mtcs::mesh::closed_mesh_problem(mesh) == "");
    CHECK(mesh.signed_volume() == Approx(prism_volume(replay / (stem + ".bores.csv"))).epsilon(1e-5));
    CHECK(fs::exists(replay / (stem + ".layout.yaml")));
  }
}

TEST_CASE("mtcs replay: the run keeps its mold, moved, deleted or edited molds are named", "[cli][replay]") {
  using mtcs_test::run_mtcs_err;
  const fs::path dir = scratch("moved");
  fs::remove_all(dir);
  fs::create_directories(dir / "a" / "meshes");
  // A primitive mold (plate) and a mold with a mesh file (cup), each in a folder of its own.
  fs::copy_file(MTCS_SOURCE_DIR + "/molds/plate_wall_distance.yaml", dir / "a" / "plate.yaml");  // fast: wall distances
  fs::copy_file(MTCS_SOURCE_DIR + "/molds/cup.yaml", dir / "a" / "cup.yaml");
  fs::copy_file(MTCS_SOURCE_DIR + "/molds/meshes/cup.off", dir / "a" / "meshes" / "cup.off");
  for (const std::string mold : {"plate", "cup"})
    REQUIRE(run_mtcs("optimize " + (dir / "a" / (mold + ".yaml")).string() + " --algorithm sms-emoa --evaluations 120 --quiet --out " +
                     (dir / ("run_" + mold)).string()) == 0);
  const std::string plate_run = (dir / "run_plate").string() + " --verify --no-plots";
  const std::string cup_run = (dir / "run_cup").string() + " --verify --no-plots";
  REQUIRE(run_mtcs("replay " + plate_run) == 0);

  fs::rename(dir / "a", dir / "b");
  // The plate's spec text is in the run: the replay reproduces every objective and says why.
  auto r = run_mtcs_err("replay_moved", "replay " + plate_run);
  CHECK(r.code == 0);
  CHECK(r.err.find("is gone (moved or deleted): replayed with the spec text stored in the run") != std::string::npos);
  // The cup loads a mesh: its new place is needed, and then it is recognised as the same.
  r = run_mtcs_err("replay_moved", "replay " + cup_run);
  CHECK(r.code == 2);
  CHECK(r.err.find("--mold") != std::string::npos);
  r = run_mtcs_err("replay_moved", "replay " + cup_run + " --mold " + (dir / "b" / "cup.yaml").string());
  CHECK(r.code == 0);
  CHECK(r.err.find("the same spec and meshes as the run's") != std::string::npos);
  // An edited mesh is named.
  { std::ofstream(dir / "b" / "meshes" / "cup.off", std::ios::app) << "# edited\n"; }
  r = run_mtcs_err("replay_moved", "replay " + (dir / "run_cup").string() + " --no-plots --mold " + (dir / "b" / "cup.yaml").string());
  CHECK(r.err.find("differs from the run's mold (mesh meshes/cup.off)") != std::string::npos);
  // An edited spec that changes the scores, in place: named, and --verify fails.
  fs::rename(dir / "b", dir / "a");
  std::string plate = mtcs_test::read_text(dir / "a" / "plate.yaml");
  const auto at = plate.find("sample_spacing:");
  REQUIRE(at != std::string::npos);
  plate.replace(at, plate.find('\n', at) - at, "sample_spacing: 2.0");
  { std::ofstream(dir / "a" / "plate.yaml") << plate; }
  r = run_mtcs_err("replay_moved", "replay " + plate_run);
  CHECK(r.code == 1);
  CHECK(r.err.find("differs from the run's mold (the spec text)") != std::string::npos);
  fs::remove_all(dir);
}
