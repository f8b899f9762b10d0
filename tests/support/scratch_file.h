#pragma once
// Test input written to disk: a file with the given text in a folder of this test process, so
// that parallel test processes never share one.

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace mtcs_test {

inline std::filesystem::path write_scratch(const std::string& topic, const std::string& name, const std::string& text) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("mtcs_" + topic + "_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::filesystem::path p = dir / name;
  std::ofstream(p) << text;
  return p;
}

// A fresh (absent) path for a run folder in this process's scratch folder of `topic`: what an
// earlier test case left there is removed.
inline std::filesystem::path fresh_scratch_dir(const std::string& topic, const std::string& name) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("mtcs_" + topic + "_" + std::to_string(::getpid())) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir.parent_path());
  return dir;
}

}  // namespace mtcs_test
