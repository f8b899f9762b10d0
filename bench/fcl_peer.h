#pragma once
// FCL 0.7's cylinder-cylinder distance (GJK on support functions), the peer in benchmarks and
// an independent oracle in tests. Private to the cli module: no FCL type leaks out.

#include <memory>

#include "mtcs/geometry/primitives.h"

namespace mtcs::bench {

class FclPair {
 public:
  FclPair(const geometry::Cylinder& a, const geometry::Cylinder& b);
  ~FclPair();
  FclPair(FclPair&&) noexcept;
  // FCL's distance; 0 when FCL reports a collision (it returns -1 then).
  double distance() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace mtcs::bench
