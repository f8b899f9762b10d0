#include "mtcs/io/atomic_file.h"

#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include <unistd.h>

#include "mtcs/io/crash_point.h"

namespace mtcs::io {

AtomicFile::AtomicFile(std::string path)
    : path_(std::move(path)), tmp_(path_ + ".tmp." + std::to_string(::getpid())), out_(tmp_) {
  if (!out_) throw std::runtime_error("cannot write " + path_);
  out_.precision(17);
}

AtomicFile::~AtomicFile() {
  if (!committed_) {
    out_.close();
    std::remove(tmp_.c_str());
  }
}

void AtomicFile::commit() {
  crash_point("output");
  out_.flush();
  if (!out_) throw std::runtime_error("cannot write " + path_);
  out_.close();
  std::filesystem::rename(tmp_, path_);
  committed_ = true;
}

}  // namespace mtcs::io
