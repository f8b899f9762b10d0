// mtcs bench part: what a designer waits for on a mold with a part (issue 41). The commands run
// as a user runs them, a process each, so that their wall time holds the start, the spec's
// reading and the part's model as it is built or read from the cache; a peer binary's commands
// interleave with ours, run by run, so that both see the same machine.

#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <map>
#include <stdexcept>

#include "bench_evaluate.h"
#include "bench_part.h"
#include "mtcs/io/disk_cache.h"
#include "mtcs/run/session.h"

extern char** environ;

namespace mtcs::bench {
namespace {

namespace fs = std::filesystem;

struct Timed {
  double seconds = 0, megabytes = 0;
};

// `program` with `args`, its output dropped and MTCS_CACHE_DIR=cache: wall time and peak
// resident memory (wait4's rusage of that child alone). Throws when it fails.
Timed run_process(const std::string& program, const std::vector<std::string>& args, const fs::path& cache) {
  std::vector<std::string> env{"MTCS_CACHE_DIR=" + cache.string()};
  for (char** e = environ; *e; ++e)
    if (std::strncmp(*e, "MTCS_CACHE_DIR=", 15) != 0) env.emplace_back(*e);
  std::vector<char*> argv{const_cast<char*>(program.c_str())}, envp;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  for (std::string& e : env) envp.push_back(e.data());
  envp.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  const auto t0 = std::chrono::steady_clock::now();
  pid_t pid = 0;
  const int err = posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  if (err != 0) throw std::runtime_error("bench part: cannot run " + program + ": " + std::strerror(err));
  int status = 0;
  rusage usage{};
  if (wait4(pid, &status, 0, &usage) != pid) throw std::runtime_error("bench part: lost " + program);
  Timed t{std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), double(usage.ru_maxrss) / 1024};
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::string line = program;
    for (const std::string& a : args) line += " " + a;
    throw std::runtime_error("bench part: failed (status " + std::to_string(status) + "): " + line);
  }
  return t;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

std::string own_mtcs() {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  return ((ec ? fs::path(".") : self.parent_path()) / "mtcs").string();
}

// The benchmark's scratch folder, removed however the benchmark ends.
struct ScratchFolder {
  fs::path path = fs::temp_directory_path() / ("mtcs-bench-part-" + std::to_string(::getpid()));
  ~ScratchFolder() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

fs::path fresh_folder(const fs::path& under, const std::string& name) {
  const fs::path p = under / name;
  fs::remove_all(p);
  fs::create_directories(p);
  return p;
}

}  // namespace

int bench_part(const PartBenchOptions& o) {
  std::string layout = o.layout;
  if (layout.empty()) {
    fs::path p(o.mold);
    layout = (p.parent_path() / (p.stem().string() + ".layout.yaml")).string();
  }
  if (!fs::exists(layout)) throw std::runtime_error("bench part: no layout " + layout + " (--layout)");
  const ScratchFolder folder;
  const fs::path& scratch = folder.path;
  std::vector<std::string> programs{own_mtcs()};
  programs.insert(programs.end(), o.peers.begin(), o.peers.end());
  std::cout << "mold,program,measure,value,unit\n";
  auto row = [&](const std::string& program, const std::string& measure, double value, const std::string& unit) {
    std::cout << o.mold << ',' << program << ',' << measure << ',' << value << ',' << unit << '\n' << std::flush;
  };

  // Commands: per repeat, every program in turn; cold in an empty folder, warm in the one it filled.
  std::map<std::pair<std::size_t, std::string>, std::vector<double>> seconds, megabytes;
  const std::vector<std::string> commands{"evaluate", "thermal"};
  for (int r = 0; r < o.repeat; ++r)
    for (std::size_t p = 0; p < programs.size(); ++p)
      for (const std::string& command : commands) {
        const fs::path cache = fresh_folder(scratch, "cache");
        const std::vector<std::string> args{command, o.mold, "--layout", layout};
        for (const char* when : {"cold", "warm"}) {
          const Timed t = run_process(programs[p], args, cache);
          seconds[{p, command + "_" + when}].push_back(t.seconds);
          megabytes[{p, command + "_" + when}].push_back(t.megabytes);
        }
      }
  if (o.optimize)
    for (std::size_t p = 0; p < programs.size(); ++p) {
      const fs::path out = fresh_folder(scratch, "run");
      const Timed t = run_process(programs[p], {"optimize", o.mold, "--out", out.string(), "--seed", "1"},
                                  fresh_folder(scratch, "cache"));
      seconds[{p, "optimize"}].push_back(t.seconds);
      megabytes[{p, "optimize"}].push_back(t.megabytes);
    }
  for (const auto& [key, s] : seconds) {
    row(programs[key.first], key.second, median(s), "s");
    row(programs[key.first], key.second + "_peak", *std::max_element(megabytes[key].begin(), megabytes[key].end()), "MB");
  }

  // In this process, the cache warm: a folder our own evaluate filled.
  const fs::path warm = fresh_folder(scratch, "cache");
  run_process(programs[0], {"evaluate", o.mold, "--layout", layout}, warm);
  io::set_cache_folder(warm);
  const auto t0 = std::chrono::steady_clock::now();
  const run::Session session(o.mold);
  const mold::Genome start = session.read_layout(layout);
  session.pipeline().evaluate(start);
  row(programs[0], "first_layout", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), "s");
  const std::vector<mold::Genome> parents{start};
  const EvaluateBench child = bench_evaluate(session.pipeline(), parents,
                                             mutated_children(session.problem(), parents, o.children, o.seed), 1);
  row(programs[0], "child", child.evaluations_per_second, "per_s");
  const std::vector<mold::Genome> randoms = random_genomes(session.scene(), o.randoms + 4, 3, 5, o.seed);
  const EvaluateBench random = bench_evaluate(session.pipeline(), {randoms.begin(), randoms.begin() + 4},
                                              {randoms.begin() + 4, randoms.end()}, 1);
  row(programs[0], "random", random.evaluations_per_second, "per_s");
  rusage self{};
  getrusage(RUSAGE_SELF, &self);
  row(programs[0], "in_process_peak", double(self.ru_maxrss) / 1024, "MB");
  io::set_cache_folder(std::nullopt);
  return 0;
}

}  // namespace mtcs::bench
