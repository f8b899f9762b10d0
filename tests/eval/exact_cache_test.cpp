// The stages' exact cache (src/eval/exact_cache.h): two generations per thread. What a run keeps
// using outlives every turnover; what it stopped using is dropped after two; a value found in the
// old generation is revived into the young one.
#include "eval/exact_cache.h"

#include <array>
#include <catch2/catch.hpp>

namespace {

using Key = std::array<double, 1>;

}  // namespace

TEST_CASE("exact cache: a key in use survives the turnovers, an unused one is dropped after two", "[eval]") {
  const mtcs::eval::ExactCache<Key, int> cache(4);
  int computed = 0;
  auto get = [&](double k) { return cache.get(Key{k}, [&] { return ++computed, int(k) * 10; }); };
  CHECK(get(1) == 10);
  CHECK(get(2) == 20);
  CHECK(computed == 2);
  // 3 keys a round, 4 per generation: key 1, used every round, is never computed again; key 2,
  // used once, is computed again after two turnovers.
  for (int round = 0; round < 6; ++round) {
    CHECK(get(1) == 10);
    for (int j = 0; j < 2; ++j) get(100 + 2 * round + j);
  }
  CHECK(computed == 2 + 12);
  CHECK(get(1) == 10);
  CHECK(computed == 14);
  CHECK(get(2) == 20);
  CHECK(computed == 15);
}

TEST_CASE("exact cache: an entry of the old generation is revived, not computed", "[eval]") {
  const mtcs::eval::ExactCache<Key, int> cache(2);
  int computed = 0, revived = 0;
  auto get = [&](double k) {
    return cache.get(
        Key{k}, [&] { return ++computed, int(k); }, [&](int&& v) { return ++revived, v; });
  };
  get(1), get(2);  // young: 1, 2
  get(3);          // turnover: old 1, 2; young 3
  CHECK(get(1) == 1);
  CHECK(revived == 1);
  CHECK(computed == 3);
  CHECK(get(1) == 1);  // now young: no revival
  CHECK(revived == 1);
}
