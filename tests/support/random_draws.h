#pragma once
// Random vectors drawn in sequence. `Vec3(u(rng), u(rng), u(rng))` evaluates its arguments in an
// unspecified order (gcc right to left, clang left to right), so the same seed gave each compiler
// other test cases; drawn here x, then y, then z, every compiler tests the same ones.

#include <Eigen/Geometry>

namespace mtcs_test {

// Three values of `next()`, in that order.
template <class Next>
Eigen::Vector3d vec3_of(Next&& next) {
  const double x = next(), y = next(), z = next();
  return {x, y, z};
}

template <class Dist, class Rng>
Eigen::Vector3d draw_vec3(Dist& d, Rng& rng) {
  return vec3_of([&] { return d(rng); });
}

template <class Dist, class Rng>
Eigen::Quaterniond draw_quaternion(Dist& d, Rng& rng) {
  const double w = d(rng), x = d(rng), y = d(rng), z = d(rng);
  return {w, x, y, z};
}

}  // namespace mtcs_test
