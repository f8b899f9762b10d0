// Issue 15, item 1: island rows in the run store. A store made without them (every store before
// islands) opens, resumes and reads as before; the first island save adds the tables, and one
// transaction holds every island's generation and the archipelago's.

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <sqlite3.h>
#include <unistd.h>

#include "mtcs/io/input_error.h"
#include "mtcs/store/run_store.h"
#include "support/scratch_file.h"

using mtcs::store::RunStore;
using namespace mtcs;
namespace fs = std::filesystem;

namespace {

opt::Generation generation(int index, long evaluations, double first) {
  opt::Generation g;
  g.index = index, g.evaluations = evaluations;
  for (int r = 0; r < 3; ++r) g.population.push_back({{first + r, -0.0}, {0.5}, {{first + r}, 0, r != 2, first + r, ""}});
  return g;
}

std::string fresh(const std::string& name) {
  const fs::path p = mtcs_test::scratch_dir("island_rows") / name;
  fs::remove(p);
  fs::remove(p.string() + ".lock");
  return p.string();
}

}  // namespace

TEST_CASE("island rows: a store without islands opens, resumes and has no island rows", "[store][islands]") {
  const std::string path = fresh("plain.sqlite");
  {
    RunStore s = RunStore::create(path, {{"program", "mtcs test"}});
    s.save(generation(0, 3, 1), 0.1);
  }
  const RunStore read = RunStore::open(path);
  CHECK(read.island_summaries(0).empty());
  CHECK_FALSE(read.island_generation(0, 0));
  RunStore again = RunStore::resume(path);
  again.save(generation(1, 6, 0.5), 0.2);
  CHECK(again.last()->index == 1);
  CHECK(again.island_summaries(0).empty());
}

TEST_CASE("island rows: one row per island and generation, the archipelago's beside them", "[store][islands]") {
  const std::string path = fresh("islands.sqlite");
  {
    RunStore s = RunStore::create(path, {{"program", "mtcs test"}});
    for (int gen = 0; gen < 4; ++gen) {
      const std::vector<opt::Generation> islands{generation(gen, 3L * (gen + 1), 10.0 * gen),
                                                 generation(gen, 3L * (gen + 1), 10.0 * gen + 5)};
      opt::Generation merged = islands[0];
      merged.evaluations *= 2;
      merged.population.insert(merged.population.end(), islands[1].population.begin(), islands[1].population.end());
      s.save_islands(islands, merged, gen);
    }
  }
  const RunStore read = RunStore::open(path);
  REQUIRE(read.summaries().size() == 4);
  CHECK(read.summaries().back().evaluations == 24);
  CHECK(read.last()->population.size() == 6);
  for (int i = 0; i < 2; ++i) {
    const auto s = read.island_summaries(i);
    REQUIRE(s.size() == 4);
    CHECK(s.back().evaluations == 12);
    CHECK(s.back().best == 30.0 + 5 * i);
    CHECK(s.back().feasible_share == Approx(2.0 / 3));
  }
  const auto g = read.island_generation(1, 2);
  REQUIRE(g);
  REQUIRE(g->population.size() == 3);
  CHECK(g->population[1].x[0] == 26);
  CHECK(std::signbit(g->population[1].x[1]));
  CHECK_FALSE(g->population[2].score.feasible);
  CHECK_FALSE(read.island_generation(2, 2));
  // A generation stored twice is refused whole: no island row of it is left behind.
  RunStore again = RunStore::resume(path);
  const std::vector<opt::Generation> twice{generation(4, 15, 1), generation(3, 15, 2)};
  opt::Generation all = twice[0];
  all.population.insert(all.population.end(), twice[1].population.begin(), twice[1].population.end());
  CHECK_THROWS_WITH(again.save_islands(twice, all, 5), Catch::Contains("UNIQUE"));
  CHECK_FALSE(again.island_generation(0, 4));
  CHECK(again.last()->index == 3);
}

TEST_CASE("island rows: the archipelago is stored as references to island rows, read back in its order",
          "[store][islands]") {
  const std::string path = fresh("references.sqlite");
  const std::vector<opt::Generation> islands{generation(0, 3, 10), generation(0, 3, 5)};
  // The archipelago best first: island 1's members (5, 6, 7), then island 0's (10, 11, 12).
  store::IslandsGeneration gen{islands, {}, 0.5, {3, 4, 5, 0, 1, 2}};
  gen.merged.index = 0, gen.merged.evaluations = 6;
  for (const int j : gen.merged_from)
    gen.merged.population.push_back(islands[std::size_t(j / 3)].population[std::size_t(j % 3)]);
  {
    RunStore s = RunStore::create(path, {{"program", "mtcs test"}});
    s.save_islands({gen});
    // A reference to the wrong member is refused, and nothing of its generation is kept.
    store::IslandsGeneration wrong = gen;
    for (auto& g : wrong.islands) g.index = 1;
    wrong.merged.index = 1;
    std::swap(wrong.merged_from[0], wrong.merged_from[1]);
    CHECK_THROWS_WITH(s.save_islands({wrong}), Catch::Contains("not the island member it names"));
    CHECK(s.last()->index == 0);
  }
  const RunStore read = RunStore::open(path);
  const auto back = read.generation(0);
  REQUIRE(back);
  REQUIRE(back->population.size() == 6);
  std::vector<double> values;
  for (const auto& ind : back->population) values.push_back(ind.score.value);
  CHECK(values == std::vector<double>{5, 6, 7, 10, 11, 12});
  CHECK(std::signbit(back->population[3].x[1]));
  CHECK_FALSE(back->population[5].score.feasible);
  CHECK(read.summaries().front().best == 5);
  CHECK(read.summaries().front().feasible_share == Approx(4.0 / 6));
  // Stored once: the run's table holds no copy of the members.
  sqlite3* db = nullptr;
  REQUIRE(sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READONLY, nullptr) == SQLITE_OK);
  sqlite3_stmt* q = nullptr;
  REQUIRE(sqlite3_prepare_v2(db, "SELECT count(*) FROM individual", -1, &q, nullptr) == SQLITE_OK);
  REQUIRE(sqlite3_step(q) == SQLITE_ROW);
  CHECK(sqlite3_column_int(q, 0) == 0);
  sqlite3_finalize(q);
  sqlite3_close(db);
}

TEST_CASE("island rows: island tables of an older store (a copy of the archipelago) resume as they were",
          "[store][islands]") {
  const std::string path = fresh("older.sqlite");
  { RunStore::create(path, {{"program", "mtcs test"}}); }
  {  // the island tables as stores made before 2026-11-25 have them
    sqlite3* db = nullptr;
    REQUIRE(sqlite3_open(path.c_str(), &db) == SQLITE_OK);
    REQUIRE(sqlite3_exec(db,
                         "CREATE TABLE island_generation(island INTEGER, idx INTEGER, evaluations INTEGER, best REAL,"
                         "  feasible_share REAL, seconds REAL, PRIMARY KEY(island, idx));"
                         "CREATE TABLE island_individual(island INTEGER, generation INTEGER, rank INTEGER, genotype BLOB,"
                         "  steps BLOB, objectives BLOB, violation REAL, feasible INTEGER, value REAL, violations TEXT,"
                         "  PRIMARY KEY(island, generation, rank));",
                         nullptr, nullptr, nullptr) == SQLITE_OK);
    sqlite3_close(db);
  }
  const std::vector<opt::Generation> islands{generation(0, 3, 10), generation(0, 3, 5)};
  opt::Generation merged = islands[0];
  merged.evaluations = 6;
  merged.population.insert(merged.population.end(), islands[1].population.begin(), islands[1].population.end());
  {
    RunStore s = RunStore::resume(path);
    s.save_islands(islands, merged, 0.5);
  }
  const RunStore read = RunStore::open(path);
  REQUIRE(read.last());
  REQUIRE(read.last()->population.size() == 6);
  CHECK(read.last()->population[3].score.value == 5);
  CHECK(read.island_generation(1, 0)->population[2].score.value == 7);
}

TEST_CASE("run store: the ES's stall count survives the store, in the run's rows and the islands', older stores read 0",
          "[store][islands][restart]") {
  const std::string path = fresh("stalled.sqlite");
  {
    RunStore s = RunStore::create(path, {{"program", "mtcs test"}});
    opt::Generation g = generation(41, 3, 1);
    g.stalled = 41;
    s.save(g, 0.1);
    std::vector<opt::Generation> islands{generation(300, 6, 2), generation(300, 6, 3)};
    islands[0].stalled = 7, islands[1].stalled = 300;
    opt::Generation merged = islands[0];
    merged.evaluations = 12;
    merged.population.insert(merged.population.end(), islands[1].population.begin(), islands[1].population.end());
    s.save_islands(islands, merged, 0.2);
  }
  {
    const RunStore read = RunStore::open(path);
    CHECK(read.generation(41)->stalled == 41);
    CHECK(read.island_generation(0, 300)->stalled == 7);
    CHECK(read.island_generation(1, 300)->stalled == 300);
  }
  const std::string old = fresh("stalled_old.sqlite");
  {
    RunStore s = RunStore::create(old, {{"program", "mtcs test"}});
    s.save(generation(0, 3, 1), 0.1);
  }
  {  // the generation table as stores made before 2026-11-25 have it: no stall count
    sqlite3* db = nullptr;
    REQUIRE(sqlite3_open(old.c_str(), &db) == SQLITE_OK);
    REQUIRE(sqlite3_exec(db, "ALTER TABLE generation DROP COLUMN stalled;", nullptr, nullptr, nullptr) == SQLITE_OK);
    sqlite3_close(db);
  }
  CHECK(RunStore::open(old).generation(0)->stalled == 0);
  {
    RunStore s = RunStore::resume(old);  // adds the column
    opt::Generation g = generation(1, 6, 0.5);
    g.stalled = 1;
    s.save(g, 0.2);
  }
  const RunStore read = RunStore::open(old);
  CHECK(read.generation(0)->stalled == 0);
  CHECK(read.generation(1)->stalled == 1);
}

TEST_CASE("run store: a stall count beyond its generation's index, or negative, is a bad store, not an overflow",
          "[store][restart]") {
  for (const long bad : {-1L, 6L, 2147483647L, 9223372036854775807L}) {
    const std::string path = fresh("stalled_bad.sqlite");
    {
      RunStore s = RunStore::create(path, {{"program", "mtcs test"}});
      s.save(generation(5, 30, 1), 0.1);
    }
    {
      sqlite3* db = nullptr;
      REQUIRE(sqlite3_open(path.c_str(), &db) == SQLITE_OK);
      const std::string sql = "UPDATE generation SET stalled = " + std::to_string(bad) + " WHERE idx = 5;";
      REQUIRE(sqlite3_exec(db, sql.c_str(), nullptr, nullptr, nullptr) == SQLITE_OK);
      sqlite3_close(db);
    }
    INFO("stalled = " << bad);
    try {
      (void)RunStore::open(path).generation(5);
      FAIL("no error");
    } catch (const io::InputError& e) {
      const std::string what = e.what();
      CHECK(what.find(path) != std::string::npos);
      CHECK(what.find("stall count") != std::string::npos);
    }
  }
}
