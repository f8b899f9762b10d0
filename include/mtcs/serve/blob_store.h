#pragma once
// Uploaded files by content: DIR/blobs/sha256/ab/cd/<hash>, written once, read-only after, one
// file for equal bytes whoever uploads them. An upload is streamed to DIR/tmp under a random
// name (with the extension the readers need), counted against its limit as it arrives, checked
// while staged, and only then renamed into place: a rejected, oversized or interrupted upload
// leaves nothing in blobs/ and its staged file is removed. No client-given name is ever part of
// a path.

#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>

#include "mtcs/serve/credentials.h"

namespace mtcs::serve {

class BlobStore {
 public:
  // Empties root/tmp: uploads a killed server was receiving (hold the data folder first).
  explicit BlobStore(std::filesystem::path root);

  class Upload {
   public:
    Upload(Upload&&) noexcept;
    ~Upload();  // removes the staged file unless committed
    // Appends bytes; false (and nothing appended) once the total would pass the limit.
    bool write(const char* data, std::size_t size);
    std::size_t size() const { return size_; }
    // The staged file, complete after the last write, for a reader to check.
    const std::filesystem::path& staged() const { return staged_; }
    // Moves the staged file into the store (unless equal bytes are there already); its hash.
    std::string commit();

   private:
    friend class BlobStore;
    Upload(const BlobStore& store, std::size_t limit, const std::string& extension);
    const BlobStore* store_;
    std::filesystem::path staged_;
    std::size_t limit_, size_ = 0;
    int fd_ = -1;
    std::unique_ptr<Sha256> hash_;
    bool committed_ = false;
  };

  // extension: ".stl", ".yaml", ... (letters and digits only, else none is used).
  Upload begin(std::size_t limit, const std::string& extension) const { return Upload(*this, limit, extension); }
  // The stored file of a hash (64 lowercase hex digits, else an exception).
  std::filesystem::path path_of(const std::string& hash) const;
  const std::filesystem::path& root() const { return root_; }

 private:
  std::filesystem::path root_;
};

bool is_sha256_hex(const std::string& text);

}  // namespace mtcs::serve
