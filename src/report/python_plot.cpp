#include "mtcs/report/python_plot.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>

extern char** environ;

namespace mtcs::report {
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

// The scripts travel with the binary: PREFIX/share/mtcs beside PREFIX/bin/mtcs once installed,
// BUILD/share/mtcs beside BUILD/mtcs in the build tree (CMake copies them there).
std::vector<std::filesystem::path> script_dirs() {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  const std::filesystem::path bin = exe.parent_path();
  return {bin / ".." / "share" / "mtcs", bin / "share" / "mtcs"};
}

std::string script_path(const std::string& script) {
  const auto dirs = script_dirs();
  for (const auto& d : dirs)
    if (std::filesystem::exists(d / script)) return (d / script).lexically_normal().string();
  return dirs.empty() ? script : (dirs.front() / script).lexically_normal().string();
}

}  // namespace

std::string plot_command(const std::string& script, const std::vector<std::string>& args) {
  std::string command = std::string(kPython) + " " + script_path(script);
  for (const auto& a : args) command += " " + a;
  return command;
}

bool render_plot(const std::string& script, const std::vector<std::string>& args, std::ostream& log) {
  const std::string by_hand = plot_command(script, args);
  if (!std::filesystem::exists(kPython) || run_python({"-c", "import matplotlib"}, true) != 0) {
    log << "no plot: " << kPython << " with matplotlib is not installed (apt-get install python3-matplotlib); "
        << "render it later with: " << by_hand << "\n";
    return false;
  }
  if (!std::filesystem::exists(script_path(script))) {
    log << "no plot: " << script_path(script) << " is missing (mtcs looks for its plotting scripts in share/mtcs "
        << "beside or above its own folder; cmake --install puts them there)\n";
    return false;
  }
  std::vector<std::string> full{script_path(script)};
  full.insert(full.end(), args.begin(), args.end());
  if (run_python(full, false) != 0) {
    log << "the plot script failed; run it by hand: " << by_hand << "\n";
    return false;
  }
  return true;
}

}  // namespace mtcs::report
