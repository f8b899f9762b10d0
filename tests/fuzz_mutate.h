#pragma once
// Byte-level mutations for the readers' fuzz tests: up to `max_edits` edits, each replacing,
// erasing (up to `max_erase` characters), inserting from `alphabet`, or truncating.

#include <random>
#include <string>

namespace mtcs_test {

inline std::string mutate(std::string s, const std::string& alphabet, std::mt19937_64& rng, int max_edits,
                          int max_erase) {
  const int edits = 1 + int(rng() % unsigned(max_edits));
  for (int e = 0; e < edits && !s.empty(); ++e) {
    const std::size_t at = rng() % s.size();
    switch (rng() % 4) {
      case 0: s[at] = alphabet[rng() % alphabet.size()]; break;
      case 1: s.erase(at, 1 + rng() % unsigned(max_erase)); break;
      case 2: s.insert(at, 1, alphabet[rng() % alphabet.size()]); break;
      case 3: s.resize(at); break;
    }
  }
  return s;
}

}  // namespace mtcs_test
