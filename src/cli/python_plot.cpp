#include "python_plot.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>

extern char** environ;

namespace mtcs::cli {
namespace {

constexpr const char* kPython = "/usr/bin/python3";

// Exit status of python3 with these arguments, its stdout sent to stderr (stderr silenced when
// `quiet`); -1 when it cannot start.
int run_python(const std::vector<std::string>& args, bool quiet) {
  std::vector<char*> argv{const_cast<char*>(kPython)};
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, 2, 1);
  if (quiet) posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  const int failed = posix_spawn(&pid, kPython, &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (failed) return -1;
  int status = 0;
  if (waitpid(pid, &status, 0) != pid) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

bool render_plot(const std::string& script, const std::vector<std::string>& args, std::ostream& log) {
  const std::string path = (std::filesystem::path(MTCS_SCRIPTS_DIR) / script).string();
  std::string by_hand = std::string(kPython) + " " + path;
  for (const auto& a : args) by_hand += " " + a;
  if (!std::filesystem::exists(kPython) || run_python({"-c", "import matplotlib"}, true) != 0) {
    log << "no plot: " << kPython << " with matplotlib is not installed (apt-get install python3-matplotlib); "
        << "render it later with: " << by_hand << "\n";
    return false;
  }
  std::vector<std::string> full{path};
  full.insert(full.end(), args.begin(), args.end());
  if (run_python(full, false) != 0) {
    log << "the plot script failed; run it by hand: " << by_hand << "\n";
    return false;
  }
  return true;
}

}  // namespace mtcs::cli
