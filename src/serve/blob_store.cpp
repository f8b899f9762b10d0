#include "mtcs/serve/blob_store.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace mtcs::serve {
namespace fs = std::filesystem;

bool is_sha256_hex(const std::string& text) {
  if (text.size() != 64) return false;
  for (char c : text)
    if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
  return true;
}

BlobStore::BlobStore(fs::path root) : root_(std::move(root)) {
  fs::create_directories(root_ / "blobs" / "sha256");
  fs::create_directories(root_ / "tmp");
  // What a killed server was receiving: never acknowledged, so never stored (the caller holds the
  // data folder's lock: no other server is writing here).
  for (const auto& staged : fs::directory_iterator(root_ / "tmp")) fs::remove_all(staged.path());
}

fs::path BlobStore::path_of(const std::string& hash) const {
  if (!is_sha256_hex(hash)) throw std::invalid_argument("not a SHA-256 hash: " + hash.substr(0, 80));
  return root_ / "blobs" / "sha256" / hash.substr(0, 2) / hash.substr(2, 2) / hash;
}

BlobStore::Upload::Upload(const BlobStore& store, std::size_t limit, const std::string& extension)
    : store_(&store), limit_(limit), hash_(std::make_unique<Sha256>()) {
  bool plain = extension.size() >= 2 && extension.size() <= 8 && extension[0] == '.';
  for (std::size_t i = 1; plain && i < extension.size(); ++i)
    plain = std::isalnum(static_cast<unsigned char>(extension[i])) != 0;
  staged_ = store.root_ / "tmp" / (random_token() + (plain ? extension : ""));
  fd_ = ::open(staged_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd_ < 0) throw std::runtime_error("cannot stage an upload in " + staged_.parent_path().string() + ": " + std::strerror(errno));
}

BlobStore::Upload::Upload(Upload&& o) noexcept
    : store_(o.store_), staged_(std::move(o.staged_)), limit_(o.limit_), size_(o.size_), fd_(o.fd_),
      hash_(std::move(o.hash_)), committed_(o.committed_) {
  o.fd_ = -1;
  o.committed_ = true;  // the moved-from upload owns no file
}

BlobStore::Upload::~Upload() {
  if (fd_ >= 0) ::close(fd_);
  if (!committed_) {
    std::error_code ignored;
    fs::remove(staged_, ignored);
  }
}

bool BlobStore::Upload::write(const char* data, std::size_t size) {
  if (size > limit_ - size_) return false;
  for (std::size_t done = 0; done < size;) {
    const ssize_t n = ::write(fd_, data + done, size - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error("cannot write an upload: " + std::string(std::strerror(errno)));
    }
    done += std::size_t(n);
  }
  hash_->add(data, size);
  size_ += size;
  return true;
}

std::string BlobStore::Upload::commit() {
  if (::fsync(fd_) != 0) throw std::runtime_error("cannot sync an upload: " + std::string(std::strerror(errno)));
  ::close(fd_);
  fd_ = -1;
  const std::string hash = hash_->hex();
  const fs::path target = store_->path_of(hash);
  fs::create_directories(target.parent_path());
  if (fs::exists(target)) {
    fs::remove(staged_);
  } else {
    ::chmod(staged_.c_str(), 0400);
    fs::rename(staged_, target);  // atomic: a reader sees the whole file or none
  }
  committed_ = true;
  return hash;
}

}  // namespace mtcs::serve
