// Issue 15, item 4: kill -9 at 20 moments of `mtcs optimize` runs (a generation's rows written
// but not committed, a polish evaluation, an output file written but not renamed, a random wall
// time), on a schedule drawn from a fixed seed. After every kill the outputs that exist are
// whole (byte for byte those of the uninterrupted run), and `--resume` ends with the
// uninterrupted result: the same store rows, the same best layout and files. The kills inside
// the run come from io::crash_point (MTCS_CRASH_AT=NAME:N raises SIGKILL at the N-th pass),
// the timed ones from this process. Some resumes are killed again before they are resumed.

#include <catch2/catch.hpp>
#include <chrono>
#include <csignal>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <thread>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include "mtcs/store/run_store.h"
#include "run_mtcs.h"
#include "stored_run.h"
#include "support/paths.h"

using mtcs::store::RunStore;
using namespace mtcs_test;

namespace {

const std::string kMold = MTCS_SOURCE_DIR + "/molds/plate_wall_distance.yaml";
const std::vector<std::string> kRun{"--seed", "7", "--evaluations", "2000", "--polish", "200", "--threads", "1", "--quiet"};
const std::vector<std::string> kFiles{"best.layout.yaml", "bores.csv", "holes.csv", "bores.stl"};

// Starts mtcs ARGS (stderr to `err`) with MTCS_CRASH_AT=crash_at when that is not empty.
pid_t start(const std::vector<std::string>& args, const std::string& crash_at, const fs::path& err) {
  std::vector<std::string> argv{MTCS_BINARY};
  argv.insert(argv.end(), args.begin(), args.end());
  const pid_t pid = ::fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    const int fd = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(fd, 2);
    if (crash_at.empty()) ::unsetenv("MTCS_CRASH_AT");
    else ::setenv("MTCS_CRASH_AT", crash_at.c_str(), 1);
    std::vector<char*> c;
    for (auto& a : argv) c.push_back(a.data());
    c.push_back(nullptr);
    ::execv(c[0], c.data());
    ::_exit(127);
  }
  return pid;
}

struct Ended {
  bool killed;  // by SIGKILL
  int code;     // exit code otherwise
};

Ended wait_for(pid_t pid) {
  int status = 0;
  REQUIRE(::waitpid(pid, &status, 0) == pid);
  if (WIFSIGNALED(status)) {
    REQUIRE(WTERMSIG(status) == SIGKILL);
    return {true, 0};
  }
  return {false, WEXITSTATUS(status)};
}

std::vector<std::string> fresh_run(const fs::path& dir) {
  std::vector<std::string> a{"optimize", kMold, "--out", dir.string()};
  a.insert(a.end(), kRun.begin(), kRun.end());
  return a;
}

std::vector<std::string> resume_run(const fs::path& dir) { return {"optimize", "--resume", dir.string(), "--quiet"}; }

std::vector<std::vector<double>> rows(const fs::path& dir) { return mtcs_test::stored_rows(dir); }

nlohmann::json summary_without_time(const fs::path& dir) {
  std::ifstream in(dir / "summary.json");
  auto j = nlohmann::json::parse(in);  // throws on a half-written file
  j.erase("seconds");
  return j;
}

// The outputs a killed run left: each one whole, as the uninterrupted run writes it.
void check_whole_or_absent(const fs::path& dir, const fs::path& full, const std::string& when) {
  INFO(when);
  for (const auto& f : kFiles)
    if (fs::exists(dir / f)) CHECK(read_text(dir / f) == read_text(full / f));
  if (fs::exists(dir / "summary.json")) CHECK(summary_without_time(dir) == summary_without_time(full));
}

void check_same_result(const fs::path& dir, const fs::path& full, const std::string& when) {
  INFO(when);
  CHECK(rows(dir) == rows(full));
  for (const auto& f : kFiles) CHECK(read_text(dir / f) == read_text(full / f));
  CHECK(summary_without_time(dir) == summary_without_time(full));
}

struct Kill {
  std::string crash_at;        // MTCS_CRASH_AT of the first run, or empty for a timed kill
  double after_seconds = 0;    // the timed kill
  std::string resume_crash_at;  // kills the first resume too, when not empty
};

// The fixed schedule: 8 kills in a generation's write, 4 in polish, 4 in the final files, 4 at
// random wall times; every other kill in a generation's write kills its resume again.
std::vector<Kill> schedule(long rows_total, long polish_calls, double run_seconds) {
  std::mt19937 rng(20261125);
  auto pick = [&](long lo, long hi) { return std::uniform_int_distribution<long>(lo, hi)(rng); };
  std::vector<Kill> out;
  for (int i = 0; i < 8; ++i)
    out.push_back({"store-row:" + std::to_string(pick(1, rows_total)), 0,
                   i % 2 ? "store-row:" + std::to_string(pick(1, 200)) : ""});
  for (int i = 0; i < 4; ++i) out.push_back({"polish:" + std::to_string(pick(1, polish_calls)), 0, ""});
  for (int i = 0; i < 4; ++i) out.push_back({"output:" + std::to_string(pick(1, 4)), 0, ""});
  for (int i = 0; i < 4; ++i)
    out.push_back({"", std::uniform_real_distribution<double>(0.0, run_seconds)(rng), ""});
  return out;
}

}  // namespace

TEST_CASE("run store faults: kill -9 at 20 moments, outputs whole or absent, every resume ends as the uninterrupted run",
          "[cli][store][faults][kill]") {
  const fs::path full = scratch("kill_resume", "full"), err = scratch("kill_resume", "run.err");
  fs::remove_all(full);
  const auto t0 = std::chrono::steady_clock::now();
  const Ended reference = wait_for(start(fresh_run(full), "", err));
  const double run_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  REQUIRE_FALSE(reference.killed);
  REQUIRE(reference.code == 0);

  long rows_total = 0;
  {
    const RunStore db = RunStore::open((full / "run.sqlite").string());
    for (const auto& s : db.summaries()) rows_total += long(db.generation(s.index)->population.size());
  }
  const long polish_calls = summary_without_time(full)["polish"]["evaluations"].get<long>() - 1;
  REQUIRE(rows_total > 100);
  REQUIRE(polish_calls > 10);

  int killed_first = 0;
  const auto plan = schedule(rows_total, polish_calls, run_seconds);
  for (std::size_t k = 0; k < plan.size(); ++k) {
    const Kill& kill = plan[k];
    const std::string when = "kill " + std::to_string(k) + ": " +
                             (kill.crash_at.empty() ? "after " + std::to_string(kill.after_seconds) + " s" : kill.crash_at);
    const fs::path dir = scratch("kill_resume", "cut" + std::to_string(k));
    fs::remove_all(dir);
    const pid_t pid = start(fresh_run(dir), kill.crash_at, err);
    if (kill.crash_at.empty()) {
      std::this_thread::sleep_for(std::chrono::duration<double>(kill.after_seconds));
      ::kill(pid, SIGKILL);
    }
    const Ended first = wait_for(pid);
    if (!kill.crash_at.empty()) {
      INFO(when);
      REQUIRE(first.killed);  // every planned place is passed by the run
    }
    if (first.killed) ++killed_first;
    else REQUIRE(first.code == 0);  // a timed kill after the run's end
    check_whole_or_absent(dir, full, when);
    if (!fs::exists(dir / "run.sqlite")) {
      // Killed before the store existed: nothing to resume, a new run is the way.
      REQUIRE(wait_for(start(fresh_run(dir), "", err)).code == 0);
    } else {
      if (!kill.resume_crash_at.empty()) {
        const Ended again = wait_for(start(resume_run(dir), kill.resume_crash_at, err));
        CHECK((again.killed || again.code == 0));
        check_whole_or_absent(dir, full, when + ", its resume killed at " + kill.resume_crash_at);
      }
      const Ended resumed = wait_for(start(resume_run(dir), "", err));
      INFO(when << ": " << read_text(err));
      REQUIRE_FALSE(resumed.killed);
      REQUIRE(resumed.code == 0);
    }
    check_same_result(dir, full, when);
    fs::remove_all(dir);
  }
  CHECK(killed_first >= 16);  // the 16 planned places at least
}

TEST_CASE("run store faults: with the ES's restart on, runs killed in a generation's write resume as the uninterrupted run",
          "[cli][store][faults][kill][restart]") {
  // A restart after 3 stalled generations: it fires several times in this short run, and the
  // kills fall before and after restarts, so the stall count must come back from the store.
  const fs::path config = scratch("kill_resume_restart", "restart.yaml"), err = scratch("kill_resume_restart", "run.err");
  { std::ofstream(config) << "es: {restart_after: 3, restart: population}\n"; }
  const auto with_restart = [&](const fs::path& dir) {
    auto a = fresh_run(dir);
    a.insert(a.end(), {"--config", config.string()});
    return a;
  };
  const fs::path full = scratch("kill_resume_restart", "full");
  fs::remove_all(full);
  REQUIRE(wait_for(start(with_restart(full), "", err)).code == 0);
  long rows_total = 0;
  int restarts = 0;
  {
    const RunStore db = RunStore::open((full / "run.sqlite").string());
    for (const auto& s : db.summaries()) {
      const auto g = db.generation(s.index);
      rows_total += long(g->population.size());
      restarts += g->stalled > 0 && g->stalled % 3 == 0 ? 1 : 0;
    }
  }
  REQUIRE(restarts >= 2);
  for (const long cut : {rows_total / 5, rows_total / 2, rows_total * 4 / 5}) {
    const std::string when = "killed at store-row:" + std::to_string(cut);
    const fs::path dir = scratch("kill_resume_restart", "cut");
    fs::remove_all(dir);
    REQUIRE(wait_for(start(with_restart(dir), "store-row:" + std::to_string(cut), err)).killed);
    const Ended resumed = wait_for(start(resume_run(dir), "", err));
    INFO(when << ": " << read_text(err));
    REQUIRE(resumed.code == 0);
    check_same_result(dir, full, when);
    fs::remove_all(dir);
  }
}
