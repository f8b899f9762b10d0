#pragma once
// The one random generator of the optimisers: xoshiro256** (Blackman & Vigna), seeded through
// splitmix64, with its own uniform and normal transforms, since the standard library's
// distributions differ between implementations. Every individual of every generation draws from
// its own generator, derived from (run seed, generation, index): same seed, same result,
// whatever the thread count.

#include <cmath>
#include <cstdint>

namespace mtcs::opt {

class Rng {
 public:
  explicit Rng(std::uint64_t seed) {
    for (auto& s : s_) s = splitmix(seed);
  }
  // The generator of individual `index` of generation `generation` of the run `seed`.
  static Rng for_individual(std::uint64_t seed, std::uint64_t generation, std::uint64_t index) {
    std::uint64_t h = seed;
    h = splitmix(h) ^ (generation * 0x9e3779b97f4a7c15ULL);
    h = splitmix(h) ^ (index * 0xc2b2ae3d27d4eb4fULL);
    return Rng(h);
  }

  std::uint64_t next() {
    const std::uint64_t result = rotl(s_[1] * 5, 7) * 9;
    const std::uint64_t t = s_[1] << 17;
    s_[2] ^= s_[0], s_[3] ^= s_[1], s_[1] ^= s_[2], s_[0] ^= s_[3];
    s_[2] ^= t;
    s_[3] = rotl(s_[3], 45);
    return result;
  }
  // Uniform in [0, 1), 53 bits.
  double uniform() { return double(next() >> 11) * 0x1.0p-53; }
  // Uniform integer in [0, n).
  int below(int n) { return int(uniform() * n); }
  // Standard normal (Marsaglia's polar method; the spare value is kept).
  double normal() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    double u, v, s;
    do {
      u = 2 * uniform() - 1, v = 2 * uniform() - 1, s = u * u + v * v;
    } while (s >= 1 || s == 0);
    const double k = std::sqrt(-2 * std::log(s) / s);
    spare_ = v * k, has_spare_ = true;
    return u * k;
  }

 private:
  static std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  static std::uint64_t splitmix(std::uint64_t& x) {
    std::uint64_t z = (x += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  std::uint64_t s_[4];
  double spare_ = 0;
  bool has_spare_ = false;
};

}  // namespace mtcs::opt
