#pragma once
// Output files appear whole or not at all: written to a temporary beside the target and renamed
// on commit; destroyed uncommitted (an error, an exception), the temporary is removed.

#include <fstream>
#include <string>

namespace mtcs::io {

class AtomicFile {
 public:
  explicit AtomicFile(std::string path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ofstream& stream() { return out_; }
  void commit();  // throws std::runtime_error when the file cannot be written

 private:
  std::string path_;
  std::string tmp_;
  std::ofstream out_;
  bool committed_ = false;
};

}  // namespace mtcs::io
