// mtcs bench access-map end to end on three public cases of one mesh (one voxelisation): the
// JSON keys, every AICA and ICA map equal to CheckBox's, CheckBox's equal to the case files'.

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "run_mtcs.h"
#include "support/paths.h"

namespace fs = std::filesystem;
using namespace mtcs_test;

TEST_CASE("mtcs bench access-map --json over three public cases", "[cli][bench][access-map]") {
  const fs::path cases = scratch("access_map_bench", "cases");
  fs::create_directories(cases);
  for (const char* name : {"drilling_mcad_herringbone_gear_p00.txt", "drilling_mcad_herringbone_gear_p04.txt",
                           "public_mcad_herringbone_gear_N128_am32_p00.txt"})
    fs::copy_file(fs::path(MTCS_TEST_DATA) / "access_maps" / name, cases / name, fs::copy_options::overwrite_existing);
  const fs::path out = scratch("access_map_bench", "bench.json");
  REQUIRE(run_mtcs("bench access-map --cases " + cases.string() + " --mesh-root " + MTCS_TEST_DATA + "/meshes --repeat 1 --json >" +
                   out.string()) == 0);
  const auto j = nlohmann::json::parse(read_text(out));
  CHECK(j.at("cases") == 3);
  CHECK(j.at("differing_cells") == 0);
  CHECK(j.at("cases_with_map") == 3);
  CHECK(j.at("checkbox_cells_differing_from_cases") == 0);
  CHECK(j.at("median_speedup_vs_checkbox").get<double>() > 0);
  CHECK(j.at("ica_efficiency").get<double>() > 0.9);  // AICA's share of node tests without CheckBox
  CHECK(j.at("ica_efficiency").get<double>() <= 1.0);
  REQUIRE(j.at("methods").size() == 3);
  for (const auto& m : j.at("methods")) {
    CHECK(m.at("differing_cells") == 0);
    CHECK(m.at("median_ms").get<double>() > 0);
    CHECK(m.at("p90_ms").get<double>() >= m.at("median_ms").get<double>());
  }
  CHECK(j.at("methods")[2].at("method") == "checkbox");
  CHECK(j.at("methods")[2].at("ica_efficiency") == 0.0);
}

TEST_CASE("mtcs bench access-map: a folder without cases exits 2", "[cli][bench][access-map]") {
  const fs::path empty = scratch("access_map_bench", "empty");
  fs::create_directories(empty);
  const Run r = run_mtcs_err("access_map_bench", "bench access-map --cases " + empty.string());
  CHECK(r.code == 2);
  CHECK(r.err.find("no case files") != std::string::npos);
}
