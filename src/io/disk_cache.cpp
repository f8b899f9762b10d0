#include "mtcs/io/disk_cache.h"

#include <atomic>
#include <cctype>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <mutex>
#include <system_error>
#include <algorithm>

#include <spdlog/spdlog.h>
#include <unistd.h>
// Header-only: nothing to link, for the installed library's users either.
#define XXH_INLINE_ALL
#include <xxhash.h>

namespace mtcs::io {
namespace fs = std::filesystem;

namespace {

// The file: magic (16 bytes), the key's digest (16), the payload's size and XXH3-64 checksum
// (8 each, little-endian as written on this machine), the payload.
constexpr char kMagic[16] = "mtcs-cache-v1\n";
constexpr std::size_t kHeader = 48;

std::mutex folder_mutex;
std::optional<fs::path> folder_in_use;

std::optional<fs::path> folder() {
  const std::lock_guard lock(folder_mutex);
  return folder_in_use;
}

// One warning per process for a folder that cannot be written: the command goes on uncached.
void warn_once(const std::string& what) {
  static std::atomic<bool> warned{false};
  if (!warned.exchange(true)) spdlog::warn("cache: {} (going on without it; --no-cache silences this)", what);
}

// Whether a file name is one of ours: kind-<32 hex>.bin, or a temporary of one (kept > 10 min:
// a writer killed mid-file). The folder may be one the user shares with other files: nothing
// else in it is counted or removed.
bool kept_file(const std::string& name) {
  const std::size_t dot = name.find(".bin");
  if (dot == std::string::npos || dot < 34 || name[dot - 33] != '-') return false;
  for (std::size_t i = dot - 32; i < dot; ++i)
    if (!std::isxdigit(static_cast<unsigned char>(name[i]))) return false;
  return name.size() == dot + 4 || name.compare(dot + 4, 5, ".tmp.") == 0;
}

// Least recently used first (a hit touches its file), until the folder's files fit the budget;
// a stale temporary first of all.
void trim(const fs::path& dir, std::uintmax_t budget) {
  std::error_code ec;
  std::vector<std::pair<fs::file_time_type, fs::directory_entry>> files;
  std::uintmax_t total = 0;
  const auto stale = fs::file_time_type::clock::now() - std::chrono::minutes(10);
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    if (!e.is_regular_file(ec) || !kept_file(name)) continue;
    const fs::file_time_type time = e.last_write_time(ec);
    if (name.find(".tmp.") != std::string::npos) {
      if (time < stale) fs::remove(e.path(), ec);
      continue;
    }
    total += e.file_size(ec);
    files.emplace_back(time, e);
  }
  if (total <= budget) return;
  std::sort(files.begin(), files.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& [time, e] : files) {
    if (total <= budget) break;
    const std::uintmax_t size = e.file_size(ec);
    if (fs::remove(e.path(), ec)) total -= size;
  }
}

// A temporary's name of its own per host, process and write: two writers of one key, threads or
// MPI ranks on hosts sharing the folder, each rename a whole file.
std::string temporary_suffix() {
  static std::atomic<unsigned> count{0};
  char host[256] = {};
  if (::gethostname(host, sizeof host - 1) != 0) host[0] = '\0';
  return ".tmp." + std::string(host) + "." + std::to_string(::getpid()) + "." + std::to_string(count++);
}

}  // namespace

CacheKey::CacheKey(std::string_view kind) : kind_(kind) { add(kind); }

CacheKey& CacheKey::add(std::span<const std::byte> bytes) {
  // Each piece prefixed by its length: ("ab", "c") and ("a", "bc") differ.
  const std::uint64_t n = bytes.size();
  const auto* size = reinterpret_cast<const std::byte*>(&n);
  bytes_.insert(bytes_.end(), size, size + sizeof n);
  bytes_.insert(bytes_.end(), bytes.begin(), bytes.end());
  return *this;
}

CacheKey& CacheKey::add(std::string_view text) { return add(std::as_bytes(std::span(text.data(), text.size()))); }

std::array<unsigned char, 16> CacheKey::digest() const {
  XXH128_canonical_t c;
  XXH128_canonicalFromHash(&c, XXH3_128bits(bytes_.data(), bytes_.size()));
  std::array<unsigned char, 16> out;
  std::memcpy(out.data(), c.digest, out.size());
  return out;
}

std::string CacheKey::file_name() const {
  static constexpr char hex[] = "0123456789abcdef";
  std::string name = kind_ + "-";
  for (const unsigned char b : digest()) name += hex[b >> 4], name += hex[b & 15];
  return name + ".bin";
}

void set_cache_folder(std::optional<fs::path> dir) {
  const std::lock_guard lock(folder_mutex);
  folder_in_use = std::move(dir);
}

std::optional<fs::path> cache_folder() { return folder(); }

std::optional<fs::path> default_cache_folder() {
  auto env = [](const char* name) -> std::optional<fs::path> {
    const char* v = std::getenv(name);
    if (v && *v) return fs::path(v);
    return std::nullopt;
  };
  std::error_code ec;
  if (auto dir = env("MTCS_CACHE_DIR")) {
    fs::path absolute = fs::absolute(*dir, ec);
    if (ec) return std::nullopt;
    return absolute;
  }
  // A relative XDG_CACHE_HOME is to be ignored (the XDG base directory specification).
  if (auto dir = env("XDG_CACHE_HOME"); dir && dir->is_absolute()) return *dir / "mtcs";
  if (auto dir = env("HOME")) return *dir / ".cache" / "mtcs";
  return std::nullopt;
}

bool cache_read(const CacheKey& key, std::span<std::byte> out) {
  const std::optional<fs::path> dir = folder();
  if (!dir) return false;
  const fs::path path = *dir / key.file_name();
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  char header[kHeader];
  if (!in.read(header, kHeader)) return false;
  std::uint64_t size, checksum;
  std::memcpy(&size, header + 32, 8);
  std::memcpy(&checksum, header + 40, 8);
  const std::array<unsigned char, 16> digest = key.digest();
  if (std::memcmp(header, kMagic, 16) != 0 || std::memcmp(header + 16, digest.data(), 16) != 0 || size != out.size())
    return false;
  if (!in.read(reinterpret_cast<char*>(out.data()), std::streamsize(out.size())) || in.peek() != EOF) return false;
  if (XXH3_64bits(out.data(), out.size()) != checksum) return false;
  std::error_code ec;
  fs::last_write_time(path, fs::file_time_type::clock::now(), ec);  // recently used: trimmed last
  return true;
}

void cache_write(const CacheKey& key, std::span<const std::byte> data, std::uintmax_t budget) {
  const std::optional<fs::path> dir = folder();
  if (!dir) return;
  std::error_code ec;
  fs::create_directories(*dir, ec);
  const fs::path path = *dir / key.file_name();
  const fs::path tmp = path.string() + temporary_suffix();
  {
    std::ofstream out(tmp, std::ios::binary);
    char header[kHeader];
    const std::uint64_t size = data.size(), checksum = XXH3_64bits(data.data(), data.size());
    const std::array<unsigned char, 16> digest = key.digest();
    std::memcpy(header, kMagic, 16);
    std::memcpy(header + 16, digest.data(), 16);
    std::memcpy(header + 32, &size, 8);
    std::memcpy(header + 40, &checksum, 8);
    out.write(header, kHeader);
    out.write(reinterpret_cast<const char*>(data.data()), std::streamsize(data.size()));
    out.close();
    if (!out) {
      fs::remove(tmp, ec);
      warn_once("cannot write " + tmp.string());
      return;
    }
  }
  fs::rename(tmp, path, ec);
  if (ec) {
    fs::remove(tmp, ec);
    warn_once("cannot write " + path.string());
    return;
  }
  trim(*dir, budget);
}

}  // namespace mtcs::io
