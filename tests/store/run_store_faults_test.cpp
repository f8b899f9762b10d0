// Faults of the run store (issue 15, item 4): a truncated, corrupted or foreign run.sqlite is
// bad input (io::InputError naming the file, exit 2 at the CLI) and is left byte for byte as it
// was; a store being written is locked, so a second writer is refused with "in use", and the
// lock dies with its process (kill -9 leaves nothing stale).

#include <catch2/catch.hpp>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <sqlite3.h>
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include "cli/run_mtcs.h"
#include "mtcs/io/input_error.h"
#include "mtcs/store/run_store.h"
#include "support/paths.h"

using mtcs::io::InputError;
using mtcs::store::RunStore;
using mtcs_test::read_text;
namespace fs = std::filesystem;

namespace {

fs::path fresh(const std::string& name) {
  const fs::path dir = mtcs_test::scratch("store_faults", name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir / "run.sqlite";
}

std::string bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

void write_bytes(const fs::path& p, const std::string& b) {
  std::ofstream(p, std::ios::binary | std::ios::trunc) << b;
}

mtcs::opt::Generation generation(int index, int size) {
  mtcs::opt::Generation g;
  g.index = index;
  g.evaluations = 10L * (index + 1);
  for (int r = 0; r < size; ++r) {
    mtcs::opt::Individual ind;
    ind.x = {1.0 * r, 2.0, 3.0, 4.0};
    ind.steps = {0.5, 0.5, 0.5, 0.5};
    ind.score = {{1.0 + r, 2.0}, 0.0, true, 1.0 + r, ""};
    g.population.push_back(ind);
  }
  return g;
}

// A whole store of `generations` generations of 40 individuals (several pages), closed.
fs::path whole_store(const std::string& name, int generations = 30) {
  const fs::path p = fresh(name);
  RunStore s = RunStore::create(p.string(), {{"program", "mtcs test"}, {"seed", "1"}});
  for (int i = 0; i < generations; ++i) s.save(generation(i, 40), 0.1 * i);
  return p;
}

// What opening `p` for reading and for resuming says; REQUIREs that both throw InputError
// naming the file and that the file is unchanged.
std::string refused(const fs::path& p) {
  const std::string before = bytes(p);
  std::string message;
  for (const bool resume : {false, true}) {
    try {
      if (resume) (void)RunStore::resume(p.string());
      else (void)RunStore::open(p.string()).last();
      FAIL("a bad store was accepted");
    } catch (const InputError& e) {
      CHECK(e.file() == p.string());
      message = e.what();
    }
  }
  CHECK(bytes(p) == before);
  // SQLite's read-only open of a WAL-mode file may leave an empty write-ahead log beside it:
  // nothing was written.
  const fs::path wal = p.string() + "-wal";
  CHECK((!fs::exists(wal) || fs::file_size(wal) == 0));
  return message;
}

}  // namespace

TEST_CASE("run store faults: a truncated run.sqlite is refused and left as it is", "[store][faults]") {
  const fs::path p = whole_store("truncated");
  const std::string whole = bytes(p);
  REQUIRE(whole.size() > 8 * 4096);
  write_bytes(p, whole.substr(0, whole.size() / 2));
  CHECK_THAT(refused(p), Catch::Contains("corrupted") || Catch::Contains("not a readable run store"));
}

TEST_CASE("run store faults: overwritten pages are refused and left as they are", "[store][faults]") {
  const fs::path p = whole_store("overwritten");
  std::string b = bytes(p);
  for (std::size_t at = 3 * 4096; at < 5 * 4096; ++at) b[at] = char(at * 31 % 251);  // pages 4 and 5
  write_bytes(p, b);
  CHECK_THAT(refused(p), Catch::Contains("run store"));
}

TEST_CASE("run store faults: a store of another program is refused and left as it is", "[store][faults]") {
  const fs::path p = fresh("foreign");
  sqlite3* db = nullptr;
  REQUIRE(sqlite3_open(p.c_str(), &db) == SQLITE_OK);
  REQUIRE(sqlite3_exec(db, "CREATE TABLE photos(id INTEGER PRIMARY KEY, name TEXT); INSERT INTO photos VALUES(1, 'x');",
                       nullptr, nullptr, nullptr) == SQLITE_OK);
  sqlite3_close(db);
  CHECK_THAT(refused(p), Catch::Contains("not a run store of mtcs"));
  // Same tables, but another program's meta: refused too.
  const fs::path q = fresh("foreign_meta");
  fs::copy_file(whole_store("foreign_source", 1), q);
  REQUIRE(sqlite3_open(q.c_str(), &db) == SQLITE_OK);
  REQUIRE(sqlite3_exec(db, "UPDATE meta SET value = 'other 1.0' WHERE key = 'program';", nullptr, nullptr, nullptr) == SQLITE_OK);
  sqlite3_close(db);
  CHECK_THAT(refused(q), Catch::Contains("no 'program' entry naming mtcs"));
}

TEST_CASE("run store faults: a text file and an empty file are no stores", "[store][faults]") {
  const fs::path p = fresh("text");
  write_bytes(p, "id,x\n1,2\n");
  CHECK_THAT(refused(p), Catch::Contains("not a readable run store"));
  write_bytes(p, "");
  CHECK_THAT(refused(p), Catch::Contains("not a run store of mtcs"));
}

// Defect found by reading for the fuzzer: a vector BLOB whose length is no multiple of 8 was
// copied whole into a vector of length/8 doubles (a heap overflow).
TEST_CASE("run store faults: a stored vector of 7 bytes is bad input, not a heap overflow", "[store][faults]") {
  const fs::path p = whole_store("ragged_blob", 1);
  sqlite3* db = nullptr;
  REQUIRE(sqlite3_open(p.c_str(), &db) == SQLITE_OK);
  REQUIRE(sqlite3_exec(db, "UPDATE individual SET genotype = x'01020304050607' WHERE rank = 3;", nullptr, nullptr,
                       nullptr) == SQLITE_OK);
  sqlite3_close(db);
  const RunStore s = RunStore::open(p.string());
  CHECK(s.summaries().size() == 1);
  try {
    (void)s.last();
    FAIL("a ragged vector was read");
  } catch (const InputError& e) {
    CHECK(e.file() == p.string());
    CHECK_THAT(std::string(e.what()), Catch::Contains("7 bytes"));
  }
}

TEST_CASE("run store faults: a second writer is refused while the run is in use", "[store][faults]") {
  const fs::path p = whole_store("in_use", 2);
  CHECK_FALSE(RunStore::in_use(p.string()));
  {
    RunStore writer = RunStore::resume(p.string());
    CHECK(RunStore::in_use(p.string()));
    CHECK_THROWS_WITH(RunStore::resume(p.string()), Catch::Contains("the run is in use"));
    CHECK_THROWS_WITH(RunStore::create(p.string(), {{"program", "mtcs test"}}), Catch::Contains("the run is in use"));
    // A reader (replay) is welcome and sees the last committed generation.
    writer.save(generation(2, 40), 1.0);
    CHECK(RunStore::open(p.string()).last()->index == 2);
    CHECK(fs::exists(p.string() + ".lock"));
  }
  // The writer's end takes its lock file along: a finished run's folder holds the store alone.
  CHECK_FALSE(fs::exists(p.string() + ".lock"));
  CHECK_FALSE(RunStore::in_use(p.string()));
  CHECK(RunStore::resume(p.string()).last()->index == 2);
  CHECK_THROWS_WITH(RunStore::create(p.string(), {{"program", "mtcs test"}}), Catch::Contains("exists here already"));
  CHECK_FALSE(fs::exists(p.string() + ".lock"));
}

TEST_CASE("run store faults: writers one after another, each alone while it writes", "[store][faults]") {
  // Each of two processes resumes the store 300 times and, while it holds it, creates and
  // removes a marker file that must not exist (O_EXCL): two writers at once would collide there.
  // The lock files come and go between them. (The narrow race lock_store's inode check closes,
  // a lock taken on a file its writer just removed, is seldom hit here: this guards the whole.)
  const fs::path p = whole_store("turns", 2);
  const std::string lock = p.string() + ".lock", marker = p.string() + ".writer";
  fs::remove(marker);
  auto writer = [&] {
    int held = 0;
    for (int k = 0; k < 300; ++k) {
      try {
        RunStore s = RunStore::resume(p.string());
        const int fd = ::open(marker.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
        if (fd < 0) return -1;  // the other writer is inside too
        ::close(fd);
        ::usleep(100);
        ::unlink(marker.c_str());
        ++held;
      } catch (const InputError&) {  // in use by the other: its turn
      }
      // A pause between turns: without it, a writer that just let go takes the lock straight
      // back, and under the sanitizers one of the two went 300 tries without a turn (CI, mine 0).
      ::usleep(200);
    }
    return held;
  };
  const pid_t child = ::fork();
  REQUIRE(child >= 0);
  if (child == 0) ::_exit(writer() < 0 ? 1 : 0);
  const int mine = writer();
  int status = 0;
  REQUIRE(::waitpid(child, &status, 0) == child);
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  CHECK(mine > 0);
  CHECK_FALSE(fs::exists(lock));
}

TEST_CASE("run store faults: kill -9 of the writer leaves no stale lock", "[store][faults]") {
  const fs::path p = fresh("killed");
  const pid_t child = ::fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    RunStore s = RunStore::create(p.string(), {{"program", "mtcs test"}});
    s.save(generation(0, 5), 0.0);
    ::raise(SIGKILL);
    ::_exit(0);
  }
  int status = 0;
  REQUIRE(::waitpid(child, &status, 0) == child);
  REQUIRE(WIFSIGNALED(status));
  REQUIRE(WTERMSIG(status) == SIGKILL);
  CHECK_FALSE(RunStore::in_use(p.string()));
  const RunStore resumed = RunStore::resume(p.string());
  CHECK(resumed.last()->population.size() == 5);
}

TEST_CASE("run store faults: mtcs replay and optimize --resume exit 2 on a corrupted store, naming it", "[store][faults]") {
  const fs::path p = whole_store("cli");
  std::string b = bytes(p);
  write_bytes(p, b.substr(0, b.size() / 3));
  const std::string before = bytes(p);
  const fs::path dir = p.parent_path();
  for (const std::string& args : {"replay " + dir.string(), "optimize --resume " + dir.string()}) {
    const auto r = mtcs_test::run_mtcs_err("store_faults", args);
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Contains(p.string()));
  }
  CHECK(bytes(p) == before);
}

// fuzz_run_store, crash-f6c2842e (tests/data/store/fuzz_malformed_meta.sqlite): a store whose
// quick check passes but whose meta page is malformed threw std::runtime_error out of the
// open's check (exit 1, no file named) instead of InputError.
TEST_CASE("run store defect: a malformed page met after the quick check is bad input", "[store][faults][fuzz-defect]") {
  const fs::path p = fresh("fuzz_malformed");
  fs::copy_file(MTCS_TEST_DATA + "/store/fuzz_malformed_meta.sqlite", p);
  CHECK_THAT(refused(p), Catch::Contains("run store"));
}

TEST_CASE("run store faults: mtcs optimize on a run in use is refused, exit 2, 'in use'", "[store][faults]") {
  const fs::path p = whole_store("cli_in_use", 2);
  const fs::path dir = p.parent_path();
  {
    const RunStore writer = RunStore::resume(p.string());  // this process writes the run
    // As the writer holds it (its opening put the store into WAL mode; its end takes it out).
    const std::string before = bytes(p);
    auto r = mtcs_test::run_mtcs_err("store_faults", "optimize --resume " + dir.string());
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Contains("the run is in use"));
    r = mtcs_test::run_mtcs_err("store_faults", "optimize " + MTCS_SOURCE_DIR + "/molds/plate.yaml --out " + dir.string());
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Contains("in use"));
    CHECK(bytes(p) == before);  // the refused runs wrote nothing
  }
}

// Found by the kill -9 test (tests/cli/kill_resume_test.cpp): a run killed while its store was
// being created left a run.sqlite without tables, which --resume refused as no run store. The
// store is now built beside its place and renamed: a kill leaves no store or a whole one.
TEST_CASE("run store faults: kill -9 while creating the store leaves no store, and a new run starts there",
          "[store][faults]") {
  const fs::path p = fresh("killed_create");
  const pid_t child = ::fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    ::setenv("MTCS_CRASH_AT", "store-create:1", 1);
    (void)RunStore::create(p.string(), {{"program", "mtcs test"}});
    ::_exit(0);
  }
  int status = 0;
  REQUIRE(::waitpid(child, &status, 0) == child);
  REQUIRE(WIFSIGNALED(status));
  CHECK(WTERMSIG(status) == SIGKILL);
  CHECK_FALSE(fs::exists(p));
  CHECK(fs::exists(p.string() + ".new"));  // the half-made store, beside
  CHECK_THROWS_WITH(RunStore::resume(p.string()), Catch::Contains("no run store here"));
  RunStore s = RunStore::create(p.string(), {{"program", "mtcs test"}});
  s.save(generation(0, 3), 0.0);
  CHECK_FALSE(fs::exists(p.string() + ".new"));
  CHECK(RunStore::open(p.string()).last()->population.size() == 3);
}

// Found by the kill -9 test (CI, 2026-12-06): a writer ends by taking its store out of WAL mode,
// a rollback-journal transaction on the file's header; killed inside it, it leaves a hot journal
// beside the store, which a read-only connection cannot roll back ("attempt to write a readonly
// database"), so --resume and replay refused the run. A writer killed in any rollback-journal
// transaction leaves the same; here one killed with its changes half on the disk (a one-page
// cache spills them before the commit).
TEST_CASE("run store faults: kill -9 inside a rollback-journal transaction: the store reads and resumes as before it",
          "[store][faults]") {
  const fs::path p = whole_store("killed_journal", 12);
  std::vector<double> bests;
  for (const auto& s : RunStore::open(p.string()).summaries()) bests.push_back(s.best);
  const pid_t child = ::fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    sqlite3* db = nullptr;
    sqlite3_open_v2(p.c_str(), &db, SQLITE_OPEN_READWRITE, nullptr);
    sqlite3_exec(db, "PRAGMA cache_size=1; BEGIN; UPDATE generation SET best = best + 1;"
                     "UPDATE individual SET value = value + 1;", nullptr, nullptr, nullptr);
    ::raise(SIGKILL);
    ::_exit(0);
  }
  int status = 0;
  REQUIRE(::waitpid(child, &status, 0) == child);
  REQUIRE(WIFSIGNALED(status));
  REQUIRE(fs::exists(p.string() + "-journal"));
  {  // hot: its writer is gone, and a read-only connection cannot roll it back
    sqlite3* db = nullptr;
    REQUIRE(sqlite3_open_v2(p.c_str(), &db, SQLITE_OPEN_READONLY, nullptr) == SQLITE_OK);
    CHECK(sqlite3_exec(db, "SELECT count(*) FROM generation", nullptr, nullptr, nullptr) != SQLITE_OK);
    CHECK(sqlite3_extended_errcode(db) == SQLITE_READONLY_ROLLBACK);
    sqlite3_close(db);
  }
  std::vector<double> read;
  for (const auto& s : RunStore::open(p.string()).summaries()) read.push_back(s.best);
  CHECK(read == bests);
  RunStore resumed = RunStore::resume(p.string());
  CHECK(resumed.last()->index == 11);
  resumed.save(generation(12, 40), 1.2);
  std::vector<double> after;
  for (const auto& s : resumed.summaries()) after.push_back(s.best);
  CHECK(after.size() == 13);
  CHECK(std::equal(bests.begin(), bests.end(), after.begin()));
}

TEST_CASE("run store faults: a text file with a journal beside it is refused, both left as they are", "[store][faults]") {
  const fs::path p = fresh("journal_beside_text");
  write_bytes(p, std::string(4096, 'x'));
  const std::string journal = std::string("\xd9\xd5\x05\xf9\x20\xa1\x63\xd7") + std::string(4088, '\1');
  write_bytes(p.string() + "-journal", journal);
  CHECK_THAT(refused(p), Catch::Contains("run store"));
  CHECK(bytes(p.string() + "-journal") == journal);
}
