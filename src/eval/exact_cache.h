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
  // At most `capacity` entries per thread; a full cache starts over (the results never depend on
  // what is cached, only the time does).
  explicit ExactCache(std::size_t capacity) : capacity_(capacity) {}

  // The value for `key`, computed by `compute()` when this thread has not seen the key. The
  // reference is valid until this thread's next call on this cache.
  template <class Compute>
  const Value& get(const Key& key, Compute&& compute) const {
    auto& map = local_.local();
    if (const auto it = map.find(key); it != map.end()) return it->second;
    if (map.size() >= capacity_) {
      map.clear();
      map.reserve(capacity_);  // one table for the next round, not a growth by doublings
    }
    // Key and value made before the insert: a flat table's slot must not see a throwing copy.
    Key k(key);
    Value v = compute();
    return map.emplace(std::move(k), std::move(v)).first->second;
  }

  // How many entries this thread's cache holds: inside `compute`, the new entry's index, below
  // the capacity (a stage may keep large values in rows of its own, reused after a start-over).
  std::size_t entries() const { return local_.local().size(); }

 private:
  // Open addressing (SwissTable): a lookup is a probe of a group of control bytes and a key
  // compare in place. std::unordered_map's was a division by a prime and a chase through two
  // nodes, each a cache miss in tables of megabytes, and an allocation per entry.
  using Map = absl::flat_hash_map<Key, Value, ExactKeyOps<Key>, ExactKeyOps<Key>>;
  std::size_t capacity_;
  mutable tbb::enumerable_thread_specific<Map> local_;
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
