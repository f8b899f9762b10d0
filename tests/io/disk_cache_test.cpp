// The disk cache of precomputes (mtcs/io/disk_cache.h): what was kept comes back bit for bit
// under its key alone; another key, another size, a damaged or cut file is a miss, never a wrong
// answer; off, nothing is read or written; the folder stays within its budget, least recently
// used out first.

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <numeric>
#include <vector>

#include "mtcs/io/disk_cache.h"
#include "support/scratch_file.h"

namespace fs = std::filesystem;
using mtcs::io::CacheKey;

namespace {

std::vector<double> values(std::size_t n, double start) {
  std::vector<double> v(n);
  std::iota(v.begin(), v.end(), start);
  v[0] = 1.0 / 3;  // bits a decimal text would round
  return v;
}

std::span<std::byte> bytes(std::vector<double>& v) { return std::as_writable_bytes(std::span(v)); }
std::span<const std::byte> bytes(const std::vector<double>& v) { return std::as_bytes(std::span(v)); }

CacheKey key_of(double x) {
  CacheKey key("test-blob");
  key.add_value(x).add("part.stl");
  return key;
}

// The cache switched to `dir` for one test, off again after it.
struct CacheIn {
  explicit CacheIn(const fs::path& dir) { mtcs::io::set_cache_folder(dir); }
  ~CacheIn() { mtcs::io::set_cache_folder(std::nullopt); }
};

}  // namespace

TEST_CASE("disk cache: kept bytes come back under their key only", "[io][cache]") {
  const fs::path dir = mtcs_test::scratch_dir("disk_cache_roundtrip");
  const CacheIn on(dir);
  const std::vector<double> kept = values(1000, 7);
  mtcs::io::cache_write(key_of(1), bytes(kept));
  REQUIRE(fs::exists(dir / key_of(1).file_name()));
  CHECK(key_of(1).file_name().rfind("test-blob-", 0) == 0);

  std::vector<double> out(1000, 0.0);
  REQUIRE(mtcs::io::cache_read(key_of(1), bytes(out)));
  CHECK(out == kept);
  CHECK_FALSE(mtcs::io::cache_read(key_of(2), bytes(out)));  // another key
  std::vector<double> shorter(999);
  CHECK_FALSE(mtcs::io::cache_read(key_of(1), bytes(shorter)));  // another size
  // Pieces are kept apart: ("ab", "c") is not ("a", "bc").
  CHECK(CacheKey("k").add("ab").add("c").file_name() != CacheKey("k").add("a").add("bc").file_name());
  CHECK(CacheKey("k").add("ab").file_name() == CacheKey("k").add("ab").file_name());
}

TEST_CASE("disk cache: a damaged or cut file is a miss", "[io][cache]") {
  const fs::path dir = mtcs_test::scratch_dir("disk_cache_damage");
  const CacheIn on(dir);
  const std::vector<double> kept = values(500, 3);
  const fs::path file = dir / key_of(5).file_name();
  std::vector<double> out(500);

  mtcs::io::cache_write(key_of(5), bytes(kept));
  {  // one bit of the payload flipped
    std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
    f.seekg(48 + 8 * 250);
    char c;
    f.read(&c, 1);
    c ^= 1;
    f.seekp(48 + 8 * 250);
    f.write(&c, 1);
  }
  CHECK_FALSE(mtcs::io::cache_read(key_of(5), bytes(out)));

  mtcs::io::cache_write(key_of(5), bytes(kept));  // rewritten whole
  REQUIRE(mtcs::io::cache_read(key_of(5), bytes(out)));
  fs::resize_file(file, fs::file_size(file) - 8);
  CHECK_FALSE(mtcs::io::cache_read(key_of(5), bytes(out)));

  mtcs::io::cache_write(key_of(5), bytes(kept));
  {  // bytes after the payload
    std::ofstream(file, std::ios::app | std::ios::binary) << "x";
  }
  CHECK_FALSE(mtcs::io::cache_read(key_of(5), bytes(out)));
  fs::resize_file(file, 20);  // a header cut short
  CHECK_FALSE(mtcs::io::cache_read(key_of(5), bytes(out)));
}

TEST_CASE("disk cache: off reads and writes nothing", "[io][cache]") {
  const fs::path dir = mtcs_test::scratch_dir("disk_cache_off");
  {
    const CacheIn on(dir);
    mtcs::io::cache_write(key_of(9), bytes(values(10, 0)));
  }
  REQUIRE(fs::exists(dir / key_of(9).file_name()));
  REQUIRE_FALSE(mtcs::io::cache_folder());
  std::vector<double> out(10);
  CHECK_FALSE(mtcs::io::cache_read(key_of(9), bytes(out)));
  mtcs::io::cache_write(key_of(10), bytes(values(10, 0)));
  CHECK_FALSE(fs::exists(dir / key_of(10).file_name()));
}

TEST_CASE("disk cache: the folder keeps to its budget, the least recently used out first", "[io][cache]") {
  const fs::path dir = mtcs_test::scratch_dir("disk_cache_budget");
  const CacheIn on(dir);
  const std::vector<double> blob = values(1000, 0);  // 8 000 bytes + a 48-byte header
  const std::uintmax_t budget = 3 * 8048;
  auto file = [&](double k) { return dir / key_of(k).file_name(); };
  const auto t0 = fs::file_time_type::clock::now() - std::chrono::hours(1);
  for (int k = 0; k < 3; ++k) {
    mtcs::io::cache_write(key_of(k), bytes(blob), budget);
    fs::last_write_time(file(k), t0 + std::chrono::minutes(k));  // written in the order 0, 1, 2
  }
  // A folder the user shares: files not the cache's are neither counted nor removed, however
  // old; a temporary a killed writer left is removed once stale.
  const fs::path user = dir / "user.bin", mine = dir / "notes-0123456789abcdef0123456789abcdef.bin.txt";
  const fs::path left = dir / (key_of(7).file_name() + ".tmp.host.1.0");
  for (const fs::path& p : {user, mine, left}) {
    std::ofstream(p) << std::string(20000, 'x');
    fs::last_write_time(p, t0 - std::chrono::hours(1));
  }
  std::vector<double> out(1000);
  REQUIRE(mtcs::io::cache_read(key_of(0), bytes(out)));  // 0 used last now
  mtcs::io::cache_write(key_of(3), bytes(blob), budget);
  CHECK(fs::exists(file(0)));
  CHECK_FALSE(fs::exists(file(1)));  // the least recently used
  CHECK(fs::exists(file(2)));
  CHECK(fs::exists(file(3)));
  CHECK(fs::exists(user));
  CHECK(fs::exists(mine));
  CHECK_FALSE(fs::exists(left));
}

TEST_CASE("disk cache: the default folder follows MTCS_CACHE_DIR, XDG_CACHE_HOME, HOME", "[io][cache]") {
  const char* names[] = {"MTCS_CACHE_DIR", "XDG_CACHE_HOME", "HOME"};
  std::vector<std::optional<std::string>> saved;
  for (const char* n : names) saved.push_back(std::getenv(n) ? std::optional<std::string>(std::getenv(n)) : std::nullopt);
  ::setenv("MTCS_CACHE_DIR", "/a/mtcs", 1);
  ::setenv("XDG_CACHE_HOME", "/b", 1);
  ::setenv("HOME", "/c", 1);
  CHECK(mtcs::io::default_cache_folder() == fs::path("/a/mtcs"));
  ::unsetenv("MTCS_CACHE_DIR");
  CHECK(mtcs::io::default_cache_folder() == fs::path("/b/mtcs"));
  ::setenv("XDG_CACHE_HOME", "relative", 1);  // ignored, as the XDG specification says
  CHECK(mtcs::io::default_cache_folder() == fs::path("/c/.cache/mtcs"));
  ::unsetenv("XDG_CACHE_HOME");
  CHECK(mtcs::io::default_cache_folder() == fs::path("/c/.cache/mtcs"));
  ::unsetenv("HOME");
  CHECK_FALSE(mtcs::io::default_cache_folder());
  ::setenv("MTCS_CACHE_DIR", "here", 1);  // made absolute
  CHECK(mtcs::io::default_cache_folder() == fs::current_path() / "here");
  ::unsetenv("MTCS_CACHE_DIR");
  for (std::size_t i = 0; i < 3; ++i)
    if (saved[i]) ::setenv(names[i], saved[i]->c_str(), 1);
}
