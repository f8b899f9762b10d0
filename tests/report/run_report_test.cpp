// The report page's data against what the run wrote by other paths: the best layout's bores
// (optimize's bores.csv), the objectives of summary.json, the violations' closest points (as
// far apart as the reported distance), the temperature of `mtcs thermal`; the page needs no
// network and stays under 5 MB; bad options are input errors.

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <nlohmann/json.hpp>

#include "cli/run_mtcs.h"
#include "mtcs/io/input_error.h"
#include "mtcs/mesh/triangle_mesh.h"
#include "mtcs/mold/mold_spec.h"
#include "mtcs/report/layout_export.h"
#include "mtcs/report/run_report.h"
#include "report/shop_member.h"
#include "mtcs/voxel/access_map_cache.h"
#include "mtcs/voxel/part_map.h"
#include "support/paths.h"

namespace {

using mtcs_test::fs::path;
using nlohmann::json;

// One small plate run per test process: 400 evaluations, generation 0 has infeasible layouts.
const path& plate_run() {
  static const path dir = [] {
    const path d = mtcs_test::scratch("report", "run");
    mtcs_test::fs::remove_all(d);
    const std::string mold = std::string(MTCS_SOURCE_DIR) + "/molds/plate.yaml";
    REQUIRE(mtcs_test::run_mtcs("optimize " + mold + " --evaluations 400 --seed 3 --quiet --out " + d.string()) == 0);
    return d;
  }();
  return dir;
}

json page_data(const std::string& html) {
  const std::string open = "<script type=\"application/json\" id=\"report-data\">";
  const std::size_t from = html.find(open) + open.size();
  return json::parse(html.substr(from, html.find("</script>", from) - from));
}

std::vector<std::vector<std::string>> read_csv(const path& p) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(mtcs_test::read_text(p));
  for (std::string line; std::getline(in, line);) {
    rows.emplace_back();
    std::istringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) rows.back().push_back(cell);
  }
  return rows;
}

// The page's base64 back to bytes.
std::vector<std::uint8_t> unbase64(const std::string& text) {
  const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::vector<std::uint8_t> out;
  unsigned bits = 0;
  int count = 0;
  for (const char c : text) {
    if (c == '=') break;
    bits = (bits << 6) | unsigned(alphabet.find(c));
    count += 6;
    if (count >= 8) out.push_back(std::uint8_t(bits >> (count -= 8)));
  }
  return out;
}

}  // namespace

TEST_CASE("report: the page needs no network, stays small and shows the run's best layout", "[report]") {
  mtcs::report::ReportOptions options;
  options.temperature = false;
  const auto r = mtcs::report::run_report(plate_run().string(), options);
  const std::string& html = r.html;
  CHECK(html.size() < 5'000'000);
  for (const char* outside : {"src=\"http", "href=\"http", "url(http", "import(\"http", "from\"http", "from 'http"})
    CHECK(html.find(outside) == std::string::npos);
  CHECK(html.find("<script type=\"importmap\">") != std::string::npos);
  CHECK(html.find("three.js authors") != std::string::npos);  // the vendored licence

  const json data = page_data(html);
  const json summary = json::parse(mtcs_test::read_text(plate_run() / "summary.json"));
  REQUIRE(data["members"].size() == r.members);
  CHECK(data["generation"] == r.generation);
  CHECK(r.generation == summary["generations"].get<int>());  // the last stored (0: the initial population)
  const json& best = data["members"][0];
  CHECK(best["feasible"] == true);
  // The page shows each member as the shop receives it (run::shop_layout, re-scored): the best is
  // optimize's best.layout.yaml and bores.csv, exactly.
  for (std::size_t k = 0; k < data["objectives"].size(); ++k)
    CHECK(best["objectives"][k].get<double>() == summary["objectives"][data["objectives"][k]["name"].get<std::string>()].get<double>());
  // optimize's bores.csv: name, circuit, segment, p0, p1, diameter, entry face.
  const auto rows = read_csv(plate_run() / "bores.csv");
  REQUIRE(rows.size() == best["layout"]["bores"].size() + 1);
  CHECK(r.bores == rows.size() - 1);
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const json& b = best["layout"]["bores"][i - 1];
    CHECK(b["name"] == rows[i][0]);
    for (int k = 0; k < 3; ++k) {
      CHECK(b["p0"][k].get<double>() == Approx(std::stod(rows[i][3 + std::size_t(k)])).margin(1e-9));
      CHECK(b["p1"][k].get<double>() == Approx(std::stod(rows[i][6 + std::size_t(k)])).margin(1e-9));
    }
    CHECK(b["diameter"].get<double>() == std::stod(rows[i][9]));
    CHECK(b["entry_face"] == rows[i][10]);
  }
  CHECK(data["convergence"]["generation"].size() == r.generations);
  CHECK(data["temperature"].is_null());
}

TEST_CASE("report: each violated clearance is drawn between points as far apart as its distance", "[report]") {
  mtcs::report::ReportOptions options;
  options.generation = 0;
  options.member = 3;
  options.temperature = false;
  const auto r = mtcs::report::run_report(plate_run().string(), options);
  const json data = page_data(r.html);
  CHECK(data["shown"] == 3);
  std::size_t drawn = 0, infeasible = 0;
  for (const json& m : data["members"]) {
    infeasible += !m["feasible"].get<bool>();
    CHECK(m["feasible"].get<bool>() == m["violations"].empty());
    for (const json& v : m["violations"]) {
      if (!v.contains("closest")) continue;
      ++drawn;
      double d2 = 0;
      for (int k = 0; k < 3; ++k) d2 += std::pow(v["closest"][0][k].get<double>() - v["closest"][1][k].get<double>(), 2);
      const double distance = v["distance"];
      if (distance > 0) CHECK(std::sqrt(d2) == Approx(distance).margin(1e-9));
      CHECK(distance < v["margin"].get<double>());
    }
  }
  CHECK(infeasible > 0);
  CHECK(drawn > 0);
}

TEST_CASE("report: the cavity temperature equals the thermal command's for the best", "[report]") {
  const auto r = mtcs::report::run_report(plate_run().string());
  REQUIRE(r.temperature);
  const json t = page_data(r.html)["temperature"];
  const path out = plate_run().parent_path() / "thermal.json";
  REQUIRE(mtcs_test::run_mtcs("thermal " + std::string(MTCS_SOURCE_DIR) + "/molds/plate.yaml --layout " +
                              (plate_run() / "best.layout.yaml").string() + " --json > " + out.string()) == 0);
  const json expected = json::parse(mtcs_test::read_text(out));
  // The report evaluates its field's vertices too, in a model of their own: the samples' values
  // are the thermal command's to rounding of the summary.
  CHECK(t["mean"].get<double>() == Approx(expected["mean"].get<double>()).epsilon(1e-12));
  CHECK(t["std"].get<double>() == Approx(expected["std"].get<double>()).epsilon(1e-12));
  CHECK(t["min"].get<double>() <= t["mean"].get<double>());
  CHECK(t["mean"].get<double>() <= t["max"].get<double>());
}

TEST_CASE("report: each bore entry's drilling map is the access module's map of that bore pivoting there", "[report]") {
  mtcs::report::ReportOptions options;
  options.temperature = false;
  const auto r = mtcs::report::run_report(plate_run().string(), options);
  const json data = page_data(r.html);
  const json& dm = data["drilling_maps"];
  REQUIRE(dm.is_object());
  const json& bores = data["members"][dm["member"].get<std::size_t>()]["layout"]["bores"];
  REQUIRE(dm["entries"].size() == bores.size());
  CHECK(r.drilling_maps == bores.size());
  // The reference: the plate's cavity box voxelised by `mtcs access-map`'s own path on the grid
  // the page names, the bore (from the page's layout, not the maps) as its straight tool.
  const auto spec = mtcs::mold::load_mold_spec(std::string(MTCS_SOURCE_DIR) + "/molds/plate.yaml");
  const mtcs::mesh::TriangleMesh part = mtcs::mesh::box_mesh(*spec.cavity->box);
  const mtcs::voxel::SphereGrid sphere{dm["rows"].get<int>(), dm["cols"].get<int>()};
  std::size_t blocked_somewhere = 0;
  for (std::size_t i = 0; i < bores.size(); ++i) {
    const json& e = dm["entries"][i];
    const json& b = bores[i];
    CHECK(e["bore"] == b["name"]);
    const mtcs::voxel::Vec3 p0(b["p0"][0], b["p0"][1], b["p0"][2]), p1(b["p1"][0], b["p1"][1], b["p1"][2]);
    for (int k = 0; k < 3; ++k) CHECK(e["entry"][k].get<double>() == Approx(p0[k]).margin(1e-9));
    CHECK(e["radius"].get<double>() == b["diameter"].get<double>() / 2);
    const mtcs::voxel::Vec3 entry(e["entry"][0], e["entry"][1], e["entry"][2]);
    const auto ref = mtcs::voxel::part_access_map(part, dm["grid"].get<int>(), entry,
                                                  mtcs::voxel::bore_tool(e["radius"], e["length"]), sphere, {});
    CHECK(ref.grid.voxel_size == dm["voxel_size"].get<double>());
    CHECK(ref.solid_voxels == dm["solid_voxels"].get<std::size_t>());
    REQUIRE_FALSE(ref.pivot_inside);
    const auto cells = unbase64(e["map"]);
    CHECK(cells == ref.map.cells);
    CHECK(e["free"].get<long>() == long(ref.map.cells.size()) - ref.map.collisions());
    bool free = false;
    for (const auto& c : mtcs::voxel::cells_of(sphere, (p1 - p0).normalized())) free = free || !ref.map.collides(c[0], c[1]);
    CHECK(e["direction_free"].get<bool>() == free);
    blocked_somewhere += ref.map.collisions() > 0;
  }
  CHECK(dm["solid_voxels"].get<std::size_t>() > 0);  // the 3 mm plate did not fall between voxel centres
  CHECK(blocked_somewhere > 0);                       // so the maps can differ at all
}

TEST_CASE("report: the anytime curves are the rows of replay's anytime.csv", "[report][anytime]") {
  mtcs::report::ReportOptions options;
  options.temperature = false;
  options.drilling_maps = false;
  const json data = page_data(mtcs::report::run_report(plate_run().string(), options).html);
  const json& a = data["anytime"];
  REQUIRE(a.is_object());
  REQUIRE(mtcs_test::run_mtcs("replay " + plate_run().string() + " --no-plots --quiet") == 0);
  const auto rows = read_csv(plate_run() / "replay" / "anytime.csv");
  REQUIRE(rows.size() >= 3);
  REQUIRE(rows[0] == std::vector<std::string>{"generation", "evaluations", "seconds", "best_feasible", "best_so_far",
                                              "hypervolume", "hypervolume_so_far"});
  REQUIRE(a["generation"].size() == rows.size() - 1);
  // The CSV has 10 significant digits; inf (no feasible layout) is null on the page.
  const auto same = [](const json& page, const std::string& csv) {
    const double v = std::stod(csv);
    if (std::isinf(v)) return page.is_null();
    return !page.is_null() && page.get<double>() == Approx(v).epsilon(1e-9).margin(1e-12);
  };
  const char* columns[] = {"generation", "evaluations", "seconds", "best_feasible", "best_so_far", "hypervolume", "hypervolume_so_far"};
  std::size_t feasible = 0;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    REQUIRE(rows[i].size() == 7);
    for (std::size_t k = 0; k < 7; ++k) {
      INFO("row " << i << ", " << columns[k] << ": csv " << rows[i][k] << ", page " << a[columns[k]][i - 1].dump());
      CHECK(same(a[columns[k]][i - 1], rows[i][k]));
    }
    feasible += !a["best_feasible"][i - 1].is_null();
  }
  CHECK(feasible > 0);  // the curves are not empty
  // The generations are the stored ones the convergence charts read by their own path.
  CHECK(a["evaluations"] == data["convergence"]["evaluations"]);
  CHECK(a["seconds"] == data["convergence"]["seconds"]);
  CHECK(a["ref"].size() == data["objectives"].size());
}

TEST_CASE("report: a missing run, generation or member is an input error naming the option", "[report]") {
  CHECK_THROWS_AS(mtcs::report::run_report((plate_run() / "nothing").string()), mtcs::io::InputError);
  mtcs::report::ReportOptions options;
  options.temperature = false;
  options.generation = 99999;
  CHECK_THROWS_WITH(mtcs::report::run_report(plate_run().string(), options), Catch::Contains("--generation"));
  options.generation.reset();
  options.member = 1000;
  CHECK_THROWS_WITH(mtcs::report::run_report(plate_run().string(), options), Catch::Contains("--member"));
  // Through the command: exit 2 and the file named.
  const auto err = mtcs_test::scratch("report", "err.txt");
  CHECK(mtcs_test::run_mtcs("report " + plate_run().string() + " --generation 99999", err) == 2);
  CHECK(mtcs_test::read_text(err).find("run.sqlite") != std::string::npos);
}

TEST_CASE("export: every bore of the run's best layout as a closed tube of the right volume and axis", "[report][export]") {
  const auto obj = plate_run().parent_path() / "bores.obj";
  const auto vtp = plate_run().parent_path() / "bores.vtp";
  REQUIRE(mtcs_test::run_mtcs("export " + plate_run().string() + " --format obj --out " + obj.string()) == 0);
  REQUIRE(mtcs_test::run_mtcs("export " + plate_run().string() + " --format vtp --out " + vtp.string()) == 0);
  const auto rows = read_csv(plate_run() / "bores.csv");  // optimize's table of the same layout
  // The OBJ, object by object: vertices (2 rings of n, then the two cap centres) and triangles.
  struct Object {
    std::string name;
    std::vector<std::array<double, 3>> v;
    std::vector<std::array<std::size_t, 3>> f;
  };
  std::vector<Object> objects;
  std::size_t base = 1;
  std::istringstream in(mtcs_test::read_text(obj));
  for (std::string line; std::getline(in, line);) {
    std::istringstream s(line);
    std::string tag;
    s >> tag;
    if (tag == "o") {
      if (!objects.empty()) base += objects.back().v.size();
      objects.push_back({});
      s >> objects.back().name;
    } else if (tag == "v") {
      auto& p = objects.back().v.emplace_back();
      s >> p[0] >> p[1] >> p[2];
    } else if (tag == "f") {
      auto& t = objects.back().f.emplace_back();
      s >> t[0] >> t[1] >> t[2];
      for (auto& i : t) i -= base;
    }
  }
  REQUIRE(objects.size() == rows.size() - 1);
  const int n = mtcs::report::kTubeSides;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const auto& o = objects[i];
    const auto& row = rows[i + 1];
    CHECK(o.name == row[0]);
    REQUIRE(o.v.size() == std::size_t(2 * n + 2));
    double p0[3], p1[3], length2 = 0;
    for (int k = 0; k < 3; ++k) {
      p0[k] = std::stod(row[3 + std::size_t(k)]), p1[k] = std::stod(row[6 + std::size_t(k)]);
      length2 += (p1[k] - p0[k]) * (p1[k] - p0[k]);
      CHECK(o.v[std::size_t(2 * n)][std::size_t(k)] == Approx(p0[k]).margin(1e-9));
      CHECK(o.v[std::size_t(2 * n + 1)][std::size_t(k)] == Approx(p1[k]).margin(1e-9));
    }
    // Signed volume by the divergence theorem against the n-gon prism's closed form.
    double volume = 0;
    for (const auto& t : o.f) {
      const auto &a = o.v[t[0]], &b = o.v[t[1]], &c = o.v[t[2]];
      volume += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0])) / 6;
    }
    const double r = std::stod(row[9]) / 2;
    CHECK(volume == Approx(n / 2.0 * r * r * std::sin(2 * M_PI / n) * std::sqrt(length2)).epsilon(1e-9));
  }
  const std::string v = mtcs_test::read_text(vtp);
  CHECK(v.find("NumberOfPolys=\"" + std::to_string(objects.size() * 4 * std::size_t(n)) + "\"") != std::string::npos);
  CHECK(v.find("Name=\"circuit\"") != std::string::npos);
  // STEP needs the optional OpenCASCADE component (read back in step_export_test.cpp); without it,
  // exit 2 saying how to get it, before any layout is built.
  if (!mtcs::report::step_available()) {
    const auto step = mtcs_test::run_mtcs_err("report", "export " + plate_run().string() + " --format step");
    CHECK(step.code == 2);
    CHECK(step.err.find("libocct-data-exchange-dev") != std::string::npos);
  }
}

// Issue 45, item 6: SMS-EMOA's report showed as "member 0 (best)" a layout that was not the run's
// best (53.08 against best.layout.yaml's 49.63), and its chart's best line rose above the median.
// SMS-EMOA stores its population in its own order; the best is the run's ranking's.
TEST_CASE("report and export of an SMS-EMOA run: the best shown and exported is best.layout.yaml's, at whatever rank",
          "[report][export]") {
  const path run = mtcs_test::scratch("report", "sms_run");
  mtcs_test::fs::remove_all(run);
  const std::string mold = std::string(MTCS_SOURCE_DIR) + "/molds/plate.yaml";
  REQUIRE(mtcs_test::run_mtcs("optimize " + mold + " --algorithm sms-emoa --evaluations 3000 --seed 1 --quiet --out " +
                              run.string()) == 0);
  mtcs::report::ReportOptions options;
  options.temperature = false;
  options.drilling_maps = false;
  const auto r = mtcs::report::run_report(run.string(), options);
  const json data = page_data(r.html);
  const json summary = json::parse(mtcs_test::read_text(run / "summary.json"));
  const int best = data["best"].get<int>();
  CHECK(data["shown"] == best);
  CHECK(r.member == best);
  // The best's value is optimize's best objective, and no member is better by the run's ranking
  // (SMS-EMOA's: feasible first, then the weighted value).
  const json& shown = data["members"][std::size_t(best)];
  CHECK(shown["feasible"] == true);
  CHECK(shown["value"].get<double>() == Approx(summary["best_objective"].get<double>()).epsilon(1e-12));
  for (const json& m : data["members"])
    if (m["feasible"] == true) CHECK(m["value"].get<double>() >= shown["value"].get<double>());
  // This seed's best is not rank 0: the old page labelled another layout best (checked, so that
  // the test keeps testing what it was written for).
  CHECK(best != 0);
  // The chart's best never rises above the median where every member is feasible (where some
  // are not, the feasible best may lie above infeasible members' values).
  const json& c = data["convergence"];
  int all_feasible = 0;
  for (std::size_t i = 0; i < c["best"].size(); ++i)
    if (c["feasible_share"][i].get<double>() == 1) {
      ++all_feasible;
      CHECK(c["best"][i].get<double>() <= c["median"][i].get<double>());
    }
  CHECK(all_feasible > 100);
  // One hypervolume scale (issue 45: the page's ~27 against replay's ~5 100): the chart's last
  // value is summary.json's, against the run's reference point.
  CHECK(c["hv_ref"] == data["anytime"]["ref"]);
  CHECK(c["hypervolume"][c["hypervolume"].size() - 1].get<double>() ==
        Approx(summary["hypervolume"].get<double>()).epsilon(1e-9));
  // Export's default member is that best: optimize's bores.csv.
  const path exported = mtcs_test::scratch("report", "sms_export.csv");
  REQUIRE(mtcs_test::run_mtcs("export " + run.string() + " --format csv --out " + exported.string()) == 0);
  CHECK(mtcs_test::read_text(exported) == mtcs_test::read_text(run / "bores.csv"));
}

TEST_CASE("export without --out: never over the run's own files, beside a layout file, named after it", "[report][export]") {
  // A new user's find: `export RUN_DIR --format csv` replaced optimize's bores.csv (the polished
  // best's) with the last generation's best.
  const std::string before = mtcs_test::read_text(plate_run() / "bores.csv");
  const auto err = mtcs_test::scratch("report", "export_default.err");
  REQUIRE(mtcs_test::run_mtcs("export " + plate_run().string() + " --format csv --member 1", err) == 0);
  CHECK(mtcs_test::read_text(plate_run() / "bores.csv") == before);
  const json summary = json::parse(mtcs_test::read_text(plate_run() / "summary.json"));
  const path exported = plate_run() / "exports" /
                        ("generation_" + std::to_string(summary["generations"].get<int>()) + "_member_1.csv");
  CHECK(mtcs_test::fs::exists(exported));
  CHECK(mtcs_test::read_text(err).find(exported.string()) != std::string::npos);
  // A layout file: L.yaml -> L.FORMAT beside it, the bores of bores.csv.
  const path layout = mtcs_test::scratch("report", "export_default") / "chosen.layout.yaml";
  mtcs_test::fs::create_directories(layout.parent_path());
  mtcs_test::fs::copy_file(plate_run() / "best.layout.yaml", layout, mtcs_test::fs::copy_options::overwrite_existing);
  REQUIRE(mtcs_test::run_mtcs("export " + std::string(MTCS_SOURCE_DIR) + "/molds/plate.yaml --layout " + layout.string() +
                              " --format csv") == 0);
  CHECK(mtcs_test::read_text(layout.parent_path() / "chosen.layout.csv") == before);
  // Issue 45, item 7: a bare file name (run in the layout's folder) failed with "filesystem error:
  // cannot create directories" (exit 1).
  mtcs_test::fs::remove(layout.parent_path() / "chosen.layout.csv");
  REQUIRE(std::system(("cd " + layout.parent_path().string() + " && " + MTCS_BINARY + " export " + MTCS_SOURCE_DIR +
                       "/molds/plate.yaml --layout chosen.layout.yaml --format csv 2>/dev/null").c_str()) == 0);
  CHECK(mtcs_test::read_text(layout.parent_path() / "chosen.layout.csv") == before);
}

TEST_CASE("report and export: a polished run's member 0 is best.layout.yaml's polished best, an edited file is said",
          "[report][export]") {
  const path dir = mtcs_test::scratch("report", "polished");
  mtcs_test::fs::remove_all(dir);
  const std::string mold = std::string(MTCS_SOURCE_DIR) + "/molds/plate_wall_distance.yaml";
  REQUIRE(mtcs_test::run_mtcs("optimize " + mold + " --evaluations 600 --seed 2 --polish 300 --quiet --out " + dir.string()) == 0);
  const json summary = json::parse(mtcs_test::read_text(dir / "summary.json"));
  REQUIRE(summary["polish"]["improved"].get<bool>());
  const double written = summary["best_objective"].get<double>(), stored = summary["polish"]["before"].get<double>();
  REQUIRE(written < stored - 1e-6);

  mtcs::report::ReportOptions options;
  options.temperature = false, options.drilling_maps = false;
  const auto polished = mtcs::report::run_report(dir.string(), options);
  CHECK(page_data(polished.html)["members"][0]["value"].get<double>() == Approx(written).epsilon(1e-12));
  CHECK_THAT(polished.note, Catch::Contains("the best member is the polished best of best.layout.yaml"));
  // export's member 0 is the run's bores.csv, byte for byte.
  const path csv = mtcs_test::scratch("report", "polished_member0.csv");
  REQUIRE(mtcs_test::run_mtcs("export " + dir.string() + " --format csv --out " + csv.string()) == 0);
  CHECK(mtcs_test::read_text(csv) == mtcs_test::read_text(dir / "bores.csv"));

  // best.layout.yaml gone (or edited): the stored best stands in, and the note says why.
  mtcs_test::fs::rename(dir / "best.layout.yaml", dir / "moved.layout.yaml");
  const auto fallback = mtcs::report::run_report(dir.string(), options);
  CHECK(page_data(fallback.html)["members"][0]["value"].get<double>() > written + 1e-6);
  CHECK_THAT(fallback.note, Catch::Contains("no longer holds the polished best"));
  const path stored_csv = mtcs_test::scratch("report", "stored_member0.csv");
  REQUIRE(mtcs_test::run_mtcs("export " + dir.string() + " --format csv --out " + stored_csv.string()) == 0);
  CHECK(mtcs_test::read_text(stored_csv) != mtcs_test::read_text(dir / "bores.csv"));
}
