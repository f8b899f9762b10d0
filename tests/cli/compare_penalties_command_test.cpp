// mtcs compare-penalties end to end on the demo plate with a tiny budget: the files parse and
// agree with each other (medians of runs.csv = the Markdown table, U recounted from the seeds'
// pairs), the variants really search differently, thread counts change nothing, bad input
// exits 2 naming the field.

#include <catch2/catch.hpp>
#include <algorithm>
#include <fstream>
#include <map>

#include "run_mtcs.h"
#include "support/paths.h"

using mtcs_test::has_matplotlib;
using mtcs_test::run_mtcs;
namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) { return mtcs_test::scratch("compare_penalties", name); }
std::string read(const fs::path& p) { return mtcs_test::read_text(p); }

using Row = std::map<std::string, std::string>;

std::vector<Row> read_csv(const fs::path& p) {
  std::ifstream in(p);
  std::string line;
  std::getline(in, line);
  auto split = [](const std::string& s, char sep) {
    std::vector<std::string> out;
    std::stringstream ss(s);
    std::string cell;
    while (std::getline(ss, cell, sep)) out.push_back(cell);
    return out;
  };
  const auto header = split(line, ',');
  std::vector<Row> rows;
  while (std::getline(in, line)) {
    const auto cells = split(line, ',');
    REQUIRE(cells.size() == header.size());
    Row r;
    for (std::size_t k = 0; k < header.size(); ++k) r[header[k]] = cells[k];
    rows.push_back(r);
  }
  return rows;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// The plate scored by wall distances: these runs optimise, and the temperatures would make them ~50x slower.
const std::string kMold = MTCS_SOURCE_DIR + "/molds/plate_wall_distance.yaml";
const std::string kVariants = "constrained_domination,static_quadratic,death";

}  // namespace

TEST_CASE("mtcs compare-penalties: outputs parse and the table agrees with the runs", "[cli][compare-penalties]") {
  const fs::path dir = scratch("plain");
  fs::remove_all(dir);
  // Without the reach move (tests/data/configs/no_reach.yaml): deciles then end at exact steps.
  REQUIRE(run_mtcs("compare-penalties " + kMold + " --variants " + kVariants + " --seeds 3 --evaluations 500 --config " +
                   std::string(MTCS_TEST_DATA + "/configs/no_reach.yaml") + " --out " +
                   dir.string(), scratch("plain.err")) == 0);
  for (const char* f : {"runs.csv", "feasible_share.csv", "rank_tests.csv", "summary.md"}) CHECK(fs::exists(dir / f));
  if (has_matplotlib()) CHECK(fs::file_size(dir / "penalties.png") > 1000);
  // Progress went to stderr, one line per run.
  CHECK(read(scratch("plain.err")).find("[9/9] death seed 3") != std::string::npos);

  const auto runs = read_csv(dir / "runs.csv");
  REQUIRE(runs.size() == 9);
  std::map<std::string, std::vector<double>> hv;
  std::map<std::pair<std::string, std::string>, const Row*> by_run;
  for (const auto& r : runs) {
    // One reference point for every run (derived from the mold unless --ref gives it).
    CHECK(r.at("reference_point") == runs.front().at("reference_point"));
    CHECK(std::stol(r.at("evaluations")) == 500);
    hv[r.at("variant")].push_back(std::stod(r.at("hypervolume")));
    by_run[{r.at("variant"), r.at("seed")}] = &r;
  }
  // The Markdown table: each variant's median HV as recomputed from runs.csv (6 digits printed).
  const std::string md = read(dir / "summary.md");
  CHECK(md.find("reference point (") != std::string::npos);
  for (const auto& [variant, values] : hv) {
    const auto at = md.find("| " + variant + " | ");
    REQUIRE(at != std::string::npos);
    const double table_median = std::stod(md.substr(at + variant.size() + 5));
    CHECK(table_median == Approx(median(values)).epsilon(1e-5).margin(1e-12));
  }
  // The feasible share per tenth adds up to the run's evaluations and its overall share.
  std::map<std::pair<std::string, std::string>, std::pair<long, long>> sums;
  std::map<std::pair<std::string, std::string>, int> tenths;
  for (const auto& s : read_csv(dir / "feasible_share.csv")) {
    auto& [evaluated, feasible] = sums[{s.at("variant"), s.at("seed")}];
    evaluated += std::stol(s.at("evaluated"));
    feasible += std::stol(s.at("feasible"));
    ++tenths[{s.at("variant"), s.at("seed")}];
    // SMS-EMOA steps one evaluation at a time: tenths of exactly 50.
    CHECK(std::stol(s.at("to")) == 50 * std::stol(s.at("decile")));
  }
  REQUIRE(sums.size() == 9);
  for (const auto& [run, s] : sums) {
    CHECK(tenths[run] == 10);
    CHECK(s.first == 500);
    CHECK(double(s.second) / double(s.first) == Approx(std::stod(by_run.at(run)->at("feasible_share"))).epsilon(1e-12));
  }
  // Rank tests: every pair of variants, U recounted from the seeds' pairs.
  const auto tests = read_csv(dir / "rank_tests.csv");
  REQUIRE(tests.size() == 3);
  for (const auto& t : tests) {
    double u = 0;
    for (const double a : hv.at(t.at("variant_a")))
      for (const double b : hv.at(t.at("variant_b"))) u += a > b ? 1 : a == b ? 0.5 : 0;
    CHECK(std::stod(t.at("u")) == u);
    const double p = std::stod(t.at("p"));
    CHECK(p > 0);
    CHECK(p <= 1);
  }
}

TEST_CASE("mtcs compare-penalties: the variants search differently under SMS-EMOA", "[cli][compare-penalties]") {
  // Same seeds, same initial population: were the penalty ignored, every run would repeat the
  // constrained-domination run of its seed.
  const fs::path dir = scratch("differ");
  fs::remove_all(dir);
  REQUIRE(run_mtcs("compare-penalties " + kMold + " --variants constrained_domination,static_linear --seeds 2 "
                   "--evaluations 400 --quiet --out " + dir.string()) == 0);
  const auto runs = read_csv(dir / "runs.csv");
  REQUIRE(runs.size() == 4);
  int differ = 0;
  for (std::size_t seed = 0; seed < 2; ++seed) {
    const Row &cd = runs[seed], &linear = runs[2 + seed];
    REQUIRE(cd.at("seed") == linear.at("seed"));
    differ += cd.at("feasible_share") != linear.at("feasible_share") || cd.at("hypervolume") != linear.at("hypervolume");
  }
  CHECK(differ > 0);
}

TEST_CASE("mtcs compare-penalties: same seeds, same results with 1 or 2 threads", "[cli][compare-penalties][determinism]") {
  const fs::path a = scratch("t1"), b = scratch("t2");
  fs::remove_all(a), fs::remove_all(b);
  const std::string args = "compare-penalties " + kMold + " --variants static_quadratic,death --seeds 2 --evaluations 600 "
                           "--algorithm es --quiet --out ";
  REQUIRE(run_mtcs(args + a.string() + " --threads 1") == 0);
  REQUIRE(run_mtcs(args + b.string() + " --threads 2") == 0);
  CHECK(read(a / "feasible_share.csv") == read(b / "feasible_share.csv"));
  CHECK(read(a / "rank_tests.csv") == read(b / "rank_tests.csv"));
  const auto ra = read_csv(a / "runs.csv"), rb = read_csv(b / "runs.csv");
  REQUIRE(ra.size() == rb.size());
  for (std::size_t i = 0; i < ra.size(); ++i)
    for (const char* column : {"variant", "seed", "evaluations", "hypervolume", "front_size", "feasible_share"})
      CHECK(ra[i].at(column) == rb[i].at(column));
}

TEST_CASE("mtcs compare-penalties: bad input exits 2 and names the field", "[cli][compare-penalties]") {
  const fs::path err = scratch("bad.err");
  const std::string base = "compare-penalties " + kMold + " --seeds 1 --evaluations 50 --out " + scratch("bad").string();
  CHECK(run_mtcs(base + " --variants constrained_domination,quadratic", err) == 2);
  CHECK(read(err).find("variants") != std::string::npos);
  CHECK(read(err).find("'quadratic'") != std::string::npos);
  CHECK(run_mtcs(base + " --ref 4,4", err) == 2);
  CHECK(read(err).find("ref") != std::string::npos);
  CHECK(run_mtcs(base + " --ref 4,-1,4", err) == 2);
  CHECK(read(err).find("ref") != std::string::npos);
  CHECK(run_mtcs(base + " --ref 4,x,4", err) == 2);
  CHECK(read(err).find("--ref") != std::string::npos);
  CHECK(run_mtcs(base + " --seeds 0", err) == 2);
  CHECK_FALSE(fs::exists(scratch("bad") / "runs.csv"));
}

// Issue 16, "Messages": compare-penalties wrote over an existing folder's results, and an
// unwritable --out exited 1 with a filesystem exception.
TEST_CASE("mtcs compare-penalties refuses a non-empty --out and an --out it cannot create: exit 2", "[cli][compare-penalties][issue16]") {
  const fs::path dir = scratch("taken");
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "runs.csv") << "earlier results\n";
  const std::string base = "compare-penalties " + kMold + " --variants death --seeds 1 --evaluations 50 --quiet --out ";
  const auto taken = mtcs_test::run_mtcs_err("compare_penalties", base + dir.string());
  CHECK(taken.code == 2);
  CHECK_THAT(taken.err, Catch::StartsWith("mtcs compare-penalties: --out " + dir.string() + ": the folder is not empty"));
  CHECK(read(dir / "runs.csv") == "earlier results\n");
  // An existing empty folder is fine.
  fs::remove(dir / "runs.csv");
  CHECK(run_mtcs(base + dir.string()) == 0);
  CHECK(fs::exists(dir / "runs.csv"));

  const auto cannot = mtcs_test::run_mtcs_err("compare_penalties", base + "/proc/forbidden/x");
  CHECK(cannot.code == 2);
  CHECK_THAT(cannot.err, Catch::StartsWith("mtcs compare-penalties: --out /proc/forbidden/x: cannot create the folder"));
  const auto zero = mtcs_test::run_mtcs_err("compare_penalties", "compare-penalties " + kMold + " --evaluations 0");
  CHECK(zero.code == 2);
  CHECK_THAT(zero.err, Catch::Contains("--evaluations: must be a whole number from 1 to 2000000000, got 0"));
}

TEST_CASE("issue 16: compare-penalties with its default reference point gives every variant hypervolume > 0 on a new part",
          "[cli][compare-penalties][issue16]") {
  // The first-mold part (docs/first-mold.md): the old fixed reference point of 4 per scaled
  // objective lies inside its objectives' range, and gave hypervolume 0 on most runs.
  const std::string part = MTCS_SOURCE_DIR + "/docs/first-mold/part.yaml";
  const std::string base = "compare-penalties " + part + " --seeds 2 --evaluations 2000 --quiet --out ";
  const fs::path dir = scratch("new_part"), fixed = scratch("new_part_ref4");
  fs::remove_all(dir);
  fs::remove_all(fixed);
  REQUIRE(run_mtcs(base + dir.string() + " --variants constrained_domination,static_linear,static_quadratic") == 0);
  const auto runs = read_csv(dir / "runs.csv");
  REQUIRE(runs.size() == 6);
  // Every run that ends with a feasible front has hypervolume > 0 (at 2 000 evaluations a
  // static penalty may end without one: that is the budget, not the reference point).
  int fronts = 0;
  for (const Row& r : runs) {
    INFO(r.at("variant") << " seed " << r.at("seed"));
    if (std::stoi(r.at("front_size")) == 0) continue;
    ++fronts;
    CHECK(std::stod(r.at("hypervolume")) > 0);
  }
  CHECK(fronts >= 4);
  // The old default, given by hand: the constrained-domination runs, with fronts of 10, score 0.
  // With the optimiser of then (no reach move): the reach move's layouts beat 4 on every scaled
  // objective on some seeds, which the old point then scores > 0 (experiments/defaults).
  const fs::path no_reach = scratch("no_reach.yaml");
  std::ofstream(no_reach) << "mutation: {reach: 0}\n";
  REQUIRE(run_mtcs(base + fixed.string() + " --variants constrained_domination --ref 4,4,4 --config " +
                   no_reach.string()) == 0);
  for (const Row& r : read_csv(fixed / "runs.csv")) {
    CHECK(std::stoi(r.at("front_size")) > 0);
    CHECK(std::stod(r.at("hypervolume")) == 0);
  }
}
