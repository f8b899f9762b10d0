#pragma once
// The --out folder of a command that writes results: made before any work starts, so that a
// path that cannot be written is bad input (exit 2, naming the path) rather than a crash at the
// end; and, for commands whose results would be mixed with an earlier run's, refused when it
// already holds files.

#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

#include "option_error.h"

namespace mtcs::cli {

// Creates DIR (and its parents) and checks that a file can be written in it.
inline void make_output_folder(const std::string& dir) {
  namespace fs = std::filesystem;
  const std::string option = "--out " + dir;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw option_error(option, "cannot create the folder: " + ec.message());
  if (!fs::is_directory(dir, ec)) throw option_error(option, "not a folder");
  const fs::path probe = fs::path(dir) / ".mtcs-write-test";
  const bool writable = static_cast<bool>(std::ofstream(probe));
  fs::remove(probe, ec);
  if (!writable) throw option_error(option, "cannot write in this folder");
}

// Refuses DIR when it exists and holds anything: earlier results are never overwritten or mixed.
inline void refuse_nonempty_folder(const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::is_directory(dir, ec) && !fs::is_empty(dir, ec))
    throw option_error("--out " + dir, "the folder is not empty (earlier results?): choose another --out or remove it");
}

}  // namespace mtcs::cli
