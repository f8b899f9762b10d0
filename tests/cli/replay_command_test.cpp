// mtcs replay's plots and CAD files: a PNG per replayed generation named so that the series
// sorts (when python3 has matplotlib), and per final front member an STL that our mesh reader
// reads back as a closed mesh holding exactly the volume of its bores (24-gon prisms).

#include <catch2/catch.hpp>
#include <cmath>
#include <nlohmann/json.hpp>

#include "mtcs/mesh/mesh_io.h"
#include "run_mtcs.h"

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
  REQUIRE(run_mtcs("optimize " MTCS_SOURCE_DIR "/molds/plate.yaml --algorithm sms-emoa --evaluations 400 --seed 2 --out " +
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
