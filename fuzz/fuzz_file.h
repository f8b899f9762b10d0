#pragma once
// The readers under fuzz take a path: each input is written to a file in a private temporary
// folder (one per process, so parallel fuzzers never share files) and removed afterwards.

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace mtcs::fuzz {

inline const std::filesystem::path& scratch_folder() {
  static const std::filesystem::path folder = [] {
    std::string pattern = (std::filesystem::temp_directory_path() / "mtcs-fuzz-XXXXXX").string();
    if (!mkdtemp(pattern.data())) std::abort();
    return std::filesystem::path(pattern);
  }();
  return folder;
}

// The input as a file named `name` (its extension picks the reader); removed, with the files
// SQLite keeps beside it, when this goes out of scope.
class InputFile {
 public:
  InputFile(const std::uint8_t* data, std::size_t size, const std::string& name)
      : path_((scratch_folder() / name).string()) {
    std::ofstream out(path_, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
  }
  ~InputFile() {
    for (const char* suffix : {"", "-wal", "-shm", "-journal"}) std::remove((path_ + suffix).c_str());
  }
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

}  // namespace mtcs::fuzz
