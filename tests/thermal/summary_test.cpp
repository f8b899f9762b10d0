// Area-weighted statistics of a field at the samples, against hand-computed values.
#include <catch2/catch.hpp>

#include "mtcs/thermal/model.h"

using namespace mtcs::thermal;

TEST_CASE("summarize weighs each sample by its area") {
  Samples s;
  s.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0)};
  s.weights = {1, 1, 2};
  const Summary m = summarize({10, 20, 40}, s);
  CHECK(m.mean == Approx(27.5));  // (10 + 20 + 80) / 4
  // (17.5^2 + 7.5^2 + 2 * 12.5^2) / 4 = 168.75
  CHECK(m.std == Approx(std::sqrt(168.75)));
  CHECK(m.max == 40);
  CHECK(m.hottest == 2);
}

TEST_CASE("summarize keeps the spread of a field far from zero") {
  Samples s;
  s.points.assign(2, Vec3::Zero());
  s.weights = {1, 1};
  const Summary m = summarize({1e8 + 1, 1e8 - 1}, s);
  CHECK(m.std == Approx(1.0).epsilon(1e-12));
}
