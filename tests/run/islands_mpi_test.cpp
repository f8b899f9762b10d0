// Issue 15, item 1 (MPI): `mpirun -np 4 mtcs optimize ... --islands 4` stores exactly the rows of
// `mtcs optimize ... --islands 4` in threads, for the ES (ring) and SMS-EMOA (fully connected);
// and a run interrupted in threads, resumed on 4 ranks, ends as the uninterrupted one. Built and
// run only with MPI (MTCS_WITH_MPI); ranks oversubscribe the machine, as root in CI.

#include <catch2/catch.hpp>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <unistd.h>

#include "mtcs/run/optimize_run.h"
#include "../support/scratch_file.h"
#include "mtcs/store/run_store.h"
#include "support/paths.h"

using namespace mtcs;
namespace fs = std::filesystem;

namespace {

const std::string kMold = MTCS_SOURCE_DIR + "/molds/plate_wall_distance.yaml";

fs::path scratch(const std::string& name) { return mtcs_test::fresh_scratch_dir("islands_mpi", name); }

int shell(const std::string& command) {
  const int status = std::system((command + " 2>/dev/null >/dev/null").c_str());
  return WEXITSTATUS(status);
}

std::string mpirun(int ranks) {
  return std::string(MTCS_MPIEXEC) + " --allow-run-as-root --oversubscribe -np " + std::to_string(ranks) + " ";
}

// Every stored row but the wall times, as bits.
std::vector<std::vector<std::uint64_t>> rows(const fs::path& dir, int islands) {
  const auto db = store::RunStore::open((dir / "run.sqlite").string());
  std::vector<std::vector<std::uint64_t>> out;
  auto add = [&](const opt::Generation& g, int island) {
    for (const auto& ind : g.population) {
      std::vector<std::uint64_t> row{std::uint64_t(island), std::uint64_t(g.index), std::uint64_t(g.evaluations)};
      for (const auto* v : {&ind.x, &ind.steps, &ind.score.objectives}) {
        const std::size_t at = row.size();
        row.resize(at + v->size());
        if (!v->empty()) std::memcpy(&row[at], v->data(), v->size() * sizeof(double));
      }
      std::uint64_t b[2];
      std::memcpy(&b[0], &ind.score.violation, 8), std::memcpy(&b[1], &ind.score.value, 8);
      row.insert(row.end(), b, b + 2);
      out.push_back(row);
    }
  };
  for (const auto& s : db.summaries()) add(*db.generation(s.index), -1);
  for (int i = 0; i < islands; ++i)
    for (const auto& s : db.island_summaries(i)) add(*db.island_generation(i, s.index), i);
  return out;
}

}  // namespace

TEST_CASE("islands on MPI: 4 ranks store what 4 islands in threads store", "[run][islands][mpi]") {
  for (const std::string args : {" --seed 3 --evaluations 1600 --migration-every 3 --migrants 2",
                                 " --seed 4 --evaluations 1200 --algorithm sms-emoa --topology fully-connected"}) {
    const fs::path threads = scratch("threads"), ranks = scratch("ranks");
    const std::string optimize = std::string(MTCS_BINARY) + " optimize " + kMold + " --islands 4" + args + " --out ";
    REQUIRE(shell(optimize + threads.string()) == 0);
    REQUIRE(shell(mpirun(4) + optimize + ranks.string()) == 0);
    const auto t = rows(threads, 4);
    CHECK(t.size() > 400);
    CHECK(rows(ranks, 4) == t);
  }
}

TEST_CASE("islands on MPI: a run interrupted in threads resumes on 4 ranks to the same end", "[run][islands][mpi]") {
  const fs::path whole = scratch("whole"), parts = scratch("parts");
  const std::string args = " --seed 5 --evaluations 1600 --migration-every 2 --islands 4 --out ";
  REQUIRE(shell(std::string(MTCS_BINARY) + " optimize " + kMold + args + whole.string()) == 0);
  run::OptimizeRequest r;
  r.mold = kMold, r.out = parts.string(), r.overrides.seed = 5, r.overrides.evaluations = 1600;
  r.islands.islands = 4, r.islands.migration_every = 2;
  r.prepare_out = [](const std::string& dir) { fs::create_directories(dir); };
  int calls = 0;  // stop() is read where the islands meet: stopped at generation 4 of 9
  const auto stopped =
      run::optimize_mold(r, [](const run::MoldOptimizer&, int) { return run::ProgressSink(); }, [&] { return ++calls > 2; });
  REQUIRE(stopped.interrupted);
  REQUIRE(shell(mpirun(4) + MTCS_BINARY + " optimize --resume " + parts.string()) == 0);
  CHECK(rows(parts, 4) == rows(whole, 4));
  // mpirun with a number of islands other than its ranks: refused, exit 2.
  CHECK(shell(mpirun(2) + MTCS_BINARY + " optimize " + kMold + " --islands 3 --out " + scratch("mismatch").string()) == 2);
}

TEST_CASE("islands on MPI: with a migration delay, 2 and 4 ranks store what 2 and 4 islands in threads store",
          "[run][islands][mpi]") {
  // Delayed migration (ranks send without waiting, receive the migrants of `delay` migrations
  // ago): the same rows as the same schedule in threads, for both topologies; and a run
  // interrupted in threads with migrants on their way, resumed on ranks, ends as the whole run.
  for (const int islands : {2, 4})
    for (const std::string args : {" --seed 6 --evaluations 1200 --migration-every 1 --migration-delay 2",
                                   " --seed 8 --evaluations 1000 --migration-every 2 --migration-delay 1 --algorithm sms-emoa"
                                   " --topology fully-connected"}) {
      INFO(islands << " islands," << args);
      const std::string n = std::to_string(islands);
      const fs::path threads = scratch("delay_threads_" + n), ranks = scratch("delay_ranks_" + n);
      const std::string optimize =
          std::string(MTCS_BINARY) + " optimize " + kMold + " --islands " + n + args + " --out ";
      REQUIRE(shell(optimize + threads.string()) == 0);
      REQUIRE(shell(mpirun(islands) + optimize + ranks.string()) == 0);
      const auto t = rows(threads, islands);
      CHECK(t.size() > 200);
      CHECK(rows(ranks, islands) == t);
    }
  const fs::path whole = scratch("delay_whole"), parts = scratch("delay_parts");
  REQUIRE(shell(std::string(MTCS_BINARY) + " optimize " + kMold +
                " --islands 4 --seed 9 --evaluations 1600 --migration-every 1 --migration-delay 2 --out " +
                whole.string()) == 0);
  run::OptimizeRequest r;
  r.mold = kMold, r.out = parts.string(), r.overrides.seed = 9, r.overrides.evaluations = 1600;
  r.islands.islands = 4, r.islands.migration_every = 1, r.islands.migration_delay = 2;
  r.prepare_out = [](const std::string& dir) { fs::create_directories(dir); };
  int calls = 0;
  const auto stopped =
      run::optimize_mold(r, [](const run::MoldOptimizer&, int) { return run::ProgressSink(); }, [&] { return ++calls > 2; });
  REQUIRE(stopped.interrupted);
  REQUIRE(shell(mpirun(4) + MTCS_BINARY + " optimize --resume " + parts.string()) == 0);
  CHECK(rows(parts, 4) == rows(whole, 4));
}
