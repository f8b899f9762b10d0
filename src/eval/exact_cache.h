#pragma once
// A stage's result for one bore (or one pair of bores) kept by the exact numbers it was computed
// from, per thread: an ES child shares most of its bores with its parent, and the parent's
// results are still here. The key holds every input of the computation and is compared bit for
// bit, so a result looked up is the one a recomputation would give: a cached evaluation equals a
// cold one exactly, whatever the thread or the order (tests/eval/incremental_test.cpp).

#include <absl/container/flat_hash_map.h>
#include <tbb/enumerable_thread_specific.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <utility>
#include <vector>

#include "mtcs/geometry/exact_hash.h"
#include "mtcs/geometry/primitives.h"

namespace mtcs::eval {

// Keys: a fixed number of doubles (a bore, a pair) or a run of them (a circuit).
template <class Key>
struct ExactKeyOps {
  std::size_t operator()(const Key& k) const {
    return geometry::exact_bits_hash(k.data(), k.size(), k.size());
  }
  bool operator()(const Key& a, const Key& b) const {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
  }
};

template <class Key, class Value>
class ExactCache {
 public:
  // Two generations of at most `capacity` entries each, per thread. New entries go into the young
  // one; when it is full it becomes the old one and the old one is dropped. An entry found in the
  // old generation moves back into the young one, so what a run keeps using (the parents' bores)
  // outlives every turnover, while both tables stay small enough for the processor's cache: a
  // lookup that misses it costs about what a recomputation saves (experiments/evaluate/es_run.md).
  // The results never depend on what is cached, only the time does.
  explicit ExactCache(std::size_t capacity) : capacity_(capacity) {}

  // The value for `key`, computed by `compute()` when this thread's cache does not hold the key.
  // The reference is valid until this thread's next call on this cache.
  template <class Compute>
  const Value& get(const Key& key, Compute&& compute) const {
    return get(key, std::forward<Compute>(compute), [](Value&& v) { return std::move(v); });
  }

  // The same, with `revive(Value&&)` making the young generation's value of an entry found in the
  // old one (a stage whose values point into storage of its own copies it there).
  template <class Compute, class Revive>
  const Value& get(const Key& key, Compute&& compute, Revive&& revive) const {
    Generations& g = local_.local();
    if (const auto it = g.young.find(key); it != g.young.end()) return it->second;
    // Key and value made before the insert: a flat table's slot must not see a throwing copy.
    Key k(key);
    const auto it = g.old.find(key);
    Value v = it != g.old.end() ? revive(std::move(it->second)) : compute();
    if (it != g.old.end()) g.old.erase(it);
    if (g.young.size() >= capacity_) {
      std::swap(g.young, g.old);
      g.young.clear();
      g.young.reserve(capacity_);  // one table for the next round, not a growth by doublings
    }
    return g.young.emplace(std::move(k), std::move(v)).first->second;
  }

 private:
  // Open addressing (SwissTable): a lookup is a probe of a group of control bytes and a key
  // compare in place. std::unordered_map's was a division by a prime and a chase through two
  // nodes, each a cache miss in tables of megabytes, and an allocation per entry.
  using Map = absl::flat_hash_map<Key, Value, ExactKeyOps<Key>, ExactKeyOps<Key>>;
  struct Generations {
    Map young, old;
  };
  std::size_t capacity_;
  mutable tbb::enumerable_thread_specific<Generations> local_;
};

// A bore's hole as a key: both ends, the radius, and the diameter its clearances are read at.
using HoleKey = std::array<double, 8>;
inline HoleKey hole_key(const geometry::Cylinder& c, double diameter) {
  return {c.p0.x(), c.p0.y(), c.p0.z(), c.p1.x(), c.p1.y(), c.p1.z(), c.radius, diameter};
}

// A clearance between a bore and something else, as a stage keeps it: the exact distance and
// its closest points, or only that the distance is at least the margin.
struct CachedClearance {
  bool clear = true;
  double distance = 0;
  geometry::Vec3 on_bore = geometry::Vec3::Zero(), on_other = geometry::Vec3::Zero();
};

// Two holes.
using PairKey = std::array<double, 14>;
inline PairKey pair_key(const geometry::Cylinder& a, const geometry::Cylinder& b) {
  return {a.p0.x(), a.p0.y(), a.p0.z(), a.p1.x(), a.p1.y(), a.p1.z(), a.radius,
          b.p0.x(), b.p0.y(), b.p0.z(), b.p1.x(), b.p1.y(), b.p1.z(), b.radius};
}

}  // namespace mtcs::eval
