#pragma once
// Precomputes kept on disk between commands. What depends only on the part and the block (the
// part's void as a panel matrix: seconds to build on a mesh part, milliseconds to read) is
// written once under a cache folder, in a file named by a hash of everything it depends on, and
// read back by the next command that needs it. A file is taken only whole: its size, its key and
// a checksum of its bytes must match, else the caller computes again and the file is rewritten.
// Writes are best effort (a temporary renamed into place): a folder that cannot be written costs
// a warning, never a result.
//
// Off by default (a library caller opts in with set_cache_folder); the mtcs commands use
// default_cache_folder() unless --no-cache.

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace mtcs::io {

// Every input of a precompute, fed in order; two keys name the same file only when they were fed
// the same bytes (XXH3, 128 bits).
class CacheKey {
 public:
  // kind: what is kept (a file-name prefix: letters, digits, '-'), part of the key.
  explicit CacheKey(std::string_view kind);

  CacheKey& add(std::span<const std::byte> bytes);
  CacheKey& add(std::string_view text);
  template <class T>
    requires std::is_trivially_copyable_v<T>
  CacheKey& add_values(std::span<const T> values) {
    return add(std::as_bytes(values));
  }
  template <class T>
    requires std::is_arithmetic_v<T>
  CacheKey& add_value(T value) {
    return add_values(std::span<const T>(&value, 1));
  }

  // kind-<32 hex digits>.bin
  std::string file_name() const;
  // The key's 16-byte digest, as stored in the file's header.
  std::array<unsigned char, 16> digest() const;

 private:
  std::string kind_;
  std::vector<std::byte> bytes_;
};

// The folder the cache lives in; none: off.
void set_cache_folder(std::optional<std::filesystem::path> folder);
std::optional<std::filesystem::path> cache_folder();
// $MTCS_CACHE_DIR (made absolute), else $XDG_CACHE_HOME/mtcs (when absolute), else
// $HOME/.cache/mtcs; none without any of them. Only the cache's own files in it are ever counted
// or removed (kind-<32 hex>.bin, and a temporary of one left by a killed writer).
std::optional<std::filesystem::path> default_cache_folder();

// The bytes kept under key, exactly out.size() of them, into out: false when the cache is off or
// holds none, or a file of another size, another key or damaged bytes (out is then unspecified).
bool cache_read(const CacheKey& key, std::span<std::byte> out);
// The folder's budget: a matrix of 3 000 panels takes 72 MB.
constexpr std::uintmax_t kCacheBytes = std::uintmax_t(1) << 30;

// Keeps data under key; then drops the least recently used files while the folder's files
// take more than `budget` bytes.
void cache_write(const CacheKey& key, std::span<const std::byte> data, std::uintmax_t budget = kCacheBytes);

}  // namespace mtcs::io
