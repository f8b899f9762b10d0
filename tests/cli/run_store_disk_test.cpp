// Issue 15, item 4: the run store under a full disk and under a reader.
// - A full disk during `mtcs optimize` (a file-size limit, RLIMIT_FSIZE, in the run's process;
//   and, where a user namespace may mount one, a tmpfs of 192 kB): the run stops with exit 1 (the
//   CLI's code for failures that are not bad input: I/O, internal errors), its message names
//   the store and says why; the store stays readable with whole generations, each as the
//   uninterrupted run stored it, and `--resume` ends with the uninterrupted result.
// - `mtcs replay` while the run writes: exit 0, the last committed generation, whole: the same
//   front as a replay of that generation from the finished run gives.

#include <catch2/catch.hpp>
#include <chrono>
#include <csignal>
#include <nlohmann/json.hpp>
#include <thread>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "mtcs/store/run_store.h"
#include "run_mtcs.h"
#include "stored_run.h"
#include "support/paths.h"
#include "support/skipped.h"

using mtcs::store::RunStore;
using namespace mtcs_test;

namespace {

const std::string kMold = MTCS_SOURCE_DIR + "/molds/plate_wall_distance.yaml";
const std::string kArgs = " --seed 7 --evaluations 2000 --threads 1 --quiet";

std::vector<std::vector<double>> rows(const fs::path& dir) { return mtcs_test::stored_rows(dir); }

// `mtcs optimize MOLD --out DIR ...` with every file it writes limited to `limit` bytes (the
// disk is full for it there); SIGXFSZ ignored, so a write beyond the limit fails with EFBIG.
int run_with_file_limit(const fs::path& dir, rlim_t limit, const fs::path& err) {
  const pid_t pid = ::fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    const int fd = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(fd, 2);
    ::signal(SIGXFSZ, SIG_IGN);
    const rlimit r{limit, limit};
    ::setrlimit(RLIMIT_FSIZE, &r);
    ::execl("/bin/sh", "sh", "-c", (std::string(MTCS_BINARY) + " optimize " + kMold + " --out " + dir.string() + kArgs).c_str(),
            nullptr);
    ::_exit(127);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  REQUIRE(WIFEXITED(status));
  return WEXITSTATUS(status);
}

// What a store cut short by a full disk holds, and its resume.
void check_cut_store_resumes(const fs::path& dir, const fs::path& full) {
  const auto cut = rows(dir), whole = rows(full);
  REQUIRE(!cut.empty());
  REQUIRE(cut.size() < whole.size());
  // Whole generations only, each as the uninterrupted run stored it.
  CHECK(std::equal(cut.begin(), cut.end(), whole.begin()));
  CHECK(cut.size() % (1 + 3 * RunStore::open((dir / "run.sqlite").string()).last()->population.size()) == 0);
  CHECK_FALSE(fs::exists(dir / "best.layout.yaml"));
  const auto resumed = run_mtcs_err("store_disk", "optimize --resume " + dir.string() + " --quiet");
  INFO(resumed.err);
  REQUIRE(resumed.code == 0);
  CHECK(rows(dir) == whole);
  CHECK(read_text(dir / "best.layout.yaml") == read_text(full / "best.layout.yaml"));
  CHECK(read_text(dir / "bores.stl") == read_text(full / "bores.stl"));
}

fs::path uninterrupted() {
  const fs::path full = scratch("store_disk", "full");
  if (!fs::exists(full / "summary.json")) {
    fs::remove_all(full);
    REQUIRE(run_mtcs("optimize " + kMold + " --out " + full.string() + kArgs) == 0);
  }
  return full;
}

}  // namespace

TEST_CASE("run store faults: a full disk (file size limit) stops the run naming the store, it resumes to the same end",
          "[cli][store][faults][disk]") {
  const fs::path full = uninterrupted();
  const fs::path dir = scratch("store_disk", "limited"), err = scratch("store_disk", "limited.err");
  fs::remove_all(dir);
  // 64 kB: the store and a few generations of its write-ahead log fit, the whole run does not.
  CHECK(run_with_file_limit(dir, 64 * 1024, err) == 1);
  const std::string said = read_text(err);
  INFO(said);
  CHECK_THAT(said, Catch::Contains((dir / "run.sqlite").string() + ": cannot save generation "));
  CHECK_THAT(said, Catch::Contains("(File too large)"));
  CHECK_FALSE(RunStore::in_use((dir / "run.sqlite").string()));
  check_cut_store_resumes(dir, full);
}

TEST_CASE("run store faults: a full tmpfs stops the run naming the store, it resumes to the same end",
          "[cli][store][faults][disk]") {
  if (std::system("unshare -rm true 2>/dev/null") != 0) {
    mtcs_test::skipped("no user namespace to mount a small tmpfs in (the file-size-limit case covers the full disk)");
    return;
  }
  const fs::path full = uninterrupted();
  const fs::path mount = scratch("store_disk", "tmpfs"), dir = scratch("store_disk", "tmpfs_run");
  const fs::path err = scratch("store_disk", "tmpfs.err"), code = scratch("store_disk", "tmpfs.code");
  fs::remove_all(dir);
  fs::create_directories(mount);
  // In a user and mount namespace of its own: a 192 kB tmpfs, the run in it, then its folder
  // copied out (the mount ends with the namespace).
  const std::string script = "mount -t tmpfs -o size=192k mtcs_full " + mount.string() + " && " + MTCS_BINARY +
                             " optimize " + kMold + " --out " + mount.string() + "/run" + kArgs + " 2>" + err.string() +
                             "; echo $? >" + code.string() + "; cp -a " + mount.string() + "/run " + dir.string();
  REQUIRE(std::system(("unshare -rm sh -c '" + script + "'").c_str()) == 0);
  CHECK(std::stoi(read_text(code)) == 1);
  const std::string said = read_text(err);
  INFO(said);
  CHECK_THAT(said, Catch::Contains(mount.string() + "/run/run.sqlite: cannot save generation "));
  CHECK_THAT(said, Catch::Contains("database or disk is full") && Catch::Contains("(No space left on device)"));
  check_cut_store_resumes(dir, full);
}

TEST_CASE("run store faults: mtcs replay while the run writes reads the last committed generation",
          "[cli][store][faults][replay]") {
  const fs::path dir = scratch("store_disk", "replayed"), err = scratch("store_disk", "replayed.err");
  fs::remove_all(dir);
  const std::string writer_cmd = std::string(MTCS_BINARY) + " optimize " + kMold + " --out " + dir.string() +
                                 " --seed 11 --evaluations 5000000 --threads 1 --quiet";
  const pid_t writer = ::fork();
  REQUIRE(writer >= 0);
  if (writer == 0) {
    ::execl("/bin/sh", "sh", "-c", ("exec " + writer_cmd + " 2>/dev/null").c_str(), nullptr);
    ::_exit(127);
  }
  const auto stored = [&] {
    try {
      return RunStore::open((dir / "run.sqlite").string()).summaries().size();
    } catch (const std::exception&) {
      return std::size_t(0);
    }
  };
  for (int i = 0; i < 3000 && stored() < 3; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  // Replays during the run, each at the last generation committed then.
  std::vector<std::pair<int, std::string>> seen;  // generation, its front_G.json
  int during = 0, status = 0;
  bool ended = false;
  for (int k = 0; k < 4; ++k) {
    const auto r = run_mtcs_err("store_disk", "replay " + dir.string() + " --every 1000000 --no-plots --quiet");
    INFO(r.err);
    CHECK(r.code == 0);
    if (!ended && ::waitpid(writer, &status, WNOHANG) == 0) ++during;  // still writing when the replay ended
    else ended = true;
    std::ifstream in(dir / "replay" / "frames.json");
    const auto frames = nlohmann::json::parse(in);
    const int g = frames["frames"].back()["generation"].get<int>();
    seen.emplace_back(g, read_text(dir / "replay" / ("front_" + std::to_string(g) + ".json")));
  }
  // The budget outlasts the replays on any machine; the writer is then stopped as a user would.
  if (!ended) {
    ::kill(writer, SIGTERM);
    REQUIRE(::waitpid(writer, &status, 0) == writer);
  }
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 128 + SIGTERM);
  CHECK(during >= 2);  // the replays overlapped the run, or the test proves nothing
  // Each replayed generation is the one the finished run stored.
  for (const auto& [g, front] : seen) {
    INFO("generation " << g);
    REQUIRE(run_mtcs("replay " + dir.string() + " --generation " + std::to_string(g) + " --no-plots --quiet") == 0);
    CHECK(read_text(dir / "replay" / ("front_" + std::to_string(g) + ".json")) == front);
  }
}
