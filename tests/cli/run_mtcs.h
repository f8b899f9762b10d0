#pragma once
// Running the built mtcs as a user would, from CLI tests: files in the test process's scratch
// folder (support/scratch_file.h), the exit code, files read whole.

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/wait.h>

#include "support/scratch_file.h"
#include "support/paths.h"

namespace mtcs_test {

namespace fs = std::filesystem;

// DIR/name in this process's scratch folder of `topic`, e.g. scratch("replay", "run").
inline fs::path scratch(const std::string& topic, const std::string& name) { return scratch_dir(topic) / name; }

// mtcs ARGS with stderr to `err` (and `env`, NAME=VALUE ..., set for it); the exit code.
inline int run_mtcs(const std::string& args, const fs::path& err = "/dev/null", const std::string& env = "") {
  const int status = std::system((env + " " + std::string(MTCS_BINARY) + " " + args + " 2>" + err.string()).c_str());
  return WEXITSTATUS(status);
}

inline std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

struct Run {
  int code;
  std::string err;
};

// mtcs ARGS: the exit code and what it wrote to stderr (kept in the topic's scratch folder).
inline Run run_mtcs_err(const std::string& topic, const std::string& args) {
  const fs::path err = scratch(topic, "run.err");
  const int code = run_mtcs(args, err);
  return {code, read_text(err)};
}

// Whether the PNG plots can be rendered here (the commands skip them otherwise).
inline bool has_matplotlib() { return std::system("/usr/bin/python3 -c 'import matplotlib' >/dev/null 2>&1") == 0; }

}  // namespace mtcs_test
