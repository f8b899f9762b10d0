// Issue 16, item 4: Ctrl-C (SIGINT) or SIGTERM during `mtcs optimize` finishes the current
// generation, writes the best-so-far outputs, prints the --resume command and exits 128 + the
// signal; the resumed run ends exactly as an uninterrupted one.

#include <catch2/catch.hpp>
#include <chrono>
#include <csignal>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include "stored_run.h"
#include "run_mtcs.h"
#include "support/paths.h"

using mtcs::store::RunStore;
using namespace mtcs_test;

namespace {

const std::string kMold = MTCS_SOURCE_DIR + "/molds/plate_wall_distance.yaml";

// Starts `mtcs optimize MOLD --out DIR ARGS...` with stderr into `err`, sends `signal` once
// `stored` generations are in its store, and returns its exit code.
int interrupt_run(const fs::path& dir, const std::vector<std::string>& args, const fs::path& err, int signal,
                  std::size_t stored) {
  std::vector<std::string> argv{MTCS_BINARY, "optimize", kMold, "--out", dir.string()};
  argv.insert(argv.end(), args.begin(), args.end());
  const pid_t pid = ::fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    const int fd = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(fd, 2);
    std::vector<char*> c;
    for (auto& a : argv) c.push_back(a.data());
    c.push_back(nullptr);
    ::execv(c[0], c.data());
    ::_exit(127);
  }
  for (int i = 0; i < 3000 && stored_generations(dir) < stored; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ::kill(pid, signal);
  int status = 0;
  ::waitpid(pid, &status, 0);
  REQUIRE(WIFEXITED(status));
  return WEXITSTATUS(status);
}

std::vector<std::vector<double>> generations(const fs::path& dir) { return mtcs_test::stored_rows(dir); }

void check_interrupted_then_resumed(const std::vector<std::string>& args, int signal, std::size_t stored) {
  const fs::path full = scratch("interrupt", "full"), cut = scratch("interrupt", "cut"),
                 err = scratch("interrupt", "cut.err");
  fs::remove_all(full), fs::remove_all(cut);
  std::string joined;
  for (const auto& a : args) joined += " " + a;
  REQUIRE(run_mtcs("optimize " + kMold + " --out " + full.string() + joined + " --quiet") == 0);

  const int code = interrupt_run(cut, args, err, signal, stored);
  CHECK(code == 128 + signal);
  const std::string said = read_text(err);
  CHECK_THAT(said, Catch::Contains("interrupted after generation"));
  CHECK_THAT(said, Catch::Contains("continue with: mtcs optimize --resume " + cut.string()));
  // The best-so-far outputs, from the last stored generation, cut short of the budget.
  for (const char* f : {"best.layout.yaml", "bores.csv", "bores.stl", "summary.json"}) CHECK(fs::exists(cut / f));
  std::ifstream in(cut / "summary.json");
  const auto summary = nlohmann::json::parse(in);
  CHECK(summary["interrupted"].get<bool>());
  const RunStore db = RunStore::open((cut / "run.sqlite").string());
  CHECK(summary["evaluations"].get<long>() == db.last()->evaluations);
  CHECK(db.summaries().size() < RunStore::open((full / "run.sqlite").string()).summaries().size());
  // The best layout so far re-scores.
  CHECK(run_mtcs("evaluate " + kMold + " --layout " + (cut / "best.layout.yaml").string() + " > /dev/null") == 0);

  // Resumed as the message says, it ends exactly where the uninterrupted run ends.
  REQUIRE(run_mtcs("optimize --resume " + cut.string() + " --quiet") == 0);
  CHECK(generations(cut) == generations(full));
  CHECK(read_text(cut / "best.layout.yaml") == read_text(full / "best.layout.yaml"));
  std::ifstream again(cut / "summary.json");
  CHECK_FALSE(nlohmann::json::parse(again)["interrupted"].get<bool>());
}

}  // namespace

TEST_CASE("issue 16: Ctrl-C in mtcs optimize writes the best so far and says how to resume (ES, SIGINT)",
          "[cli][optimize][issue16]") {
  // 200 000 evaluations (~1.5 s unloaded): 30 000 took 0.2 s, one store commit
  // (RunStore::kCommitWindow), and ended before a reader saw any generation.
  check_interrupted_then_resumed({"--seed", "11", "--evaluations", "200000"}, SIGINT, 20);
}

TEST_CASE("issue 16: SIGTERM in mtcs optimize --algorithm sms-emoa stops at a stored generation and resumes exactly",
          "[cli][optimize][issue16]") {
  // Long enough (~1 s) to span several of the store's commits (RunStore::kCommitWindow): the
  // signal goes once a reader sees 5 generations, mid-run.
  check_interrupted_then_resumed({"--seed", "2", "--evaluations", "60000", "--algorithm", "sms-emoa"}, SIGTERM, 5);
}
