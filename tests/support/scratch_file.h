#pragma once
// Test files on disk. Every test process writes under one folder of its own,
// <tmp>/mtcs_test_<pid>, and removes it when it exits: ctest runs each case in its own process
// (in parallel), so cases never share a file and a run leaves nothing behind. Set
// MTCS_KEEP_SCRATCH=1 to keep the folder for a look after a failure.

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

namespace mtcs_test {

inline const std::filesystem::path& scratch_root() {
  struct Root {
    std::filesystem::path path =
        std::filesystem::temp_directory_path() / ("mtcs_test_" + std::to_string(::getpid()));
    ~Root() {
      if (std::getenv("MTCS_KEEP_SCRATCH")) return;
      std::error_code ignored;  // a destructor at exit has no one to tell
      std::filesystem::remove_all(path, ignored);
    }
  };
  static const Root root;
  return root.path;
}

// This process's folder for `topic`, made if absent.
inline std::filesystem::path scratch_dir(const std::string& topic) {
  const std::filesystem::path dir = scratch_root() / topic;
  std::filesystem::create_directories(dir);
  return dir;
}

inline std::filesystem::path write_scratch(const std::string& topic, const std::string& name, const std::string& text) {
  const std::filesystem::path p = scratch_dir(topic) / name;
  std::ofstream(p) << text;
  return p;
}

// A fresh (absent) path for a run folder in the scratch folder of `topic`: what an earlier test
// case left there is removed.
inline std::filesystem::path fresh_scratch_dir(const std::string& topic, const std::string& name) {
  const std::filesystem::path dir = scratch_dir(topic) / name;
  std::filesystem::remove_all(dir);
  return dir;
}

}  // namespace mtcs_test
