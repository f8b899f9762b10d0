// Issue 15, item 1: island rows in the run store. A store made without them (every store before
// islands) opens, resumes and reads as before; the first island save adds the tables, and one
// transaction holds every island's generation and the archipelago's.

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <unistd.h>

#include "mtcs/store/run_store.h"

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
  const fs::path p = fs::temp_directory_path() / ("mtcs_island_rows_" + std::to_string(::getpid()) + "_" + name);
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
  CHECK_THROWS(again.save_islands({generation(4, 15, 1), generation(3, 15, 2)}, generation(4, 30, 1), 5));
  CHECK_FALSE(again.island_generation(0, 4));
  CHECK(again.last()->index == 3);
}
