#pragma once
// Standard test functions for the optimisers: sphere, ellipsoid (condition 1e6), Rosenbrock,
// on [-5, 5]^n with the minimum 0.

#include <memory>
#include <string>

#include "mtcs/opt/problem.h"

namespace mtcs::opt {

// name: sphere, ellipsoid, rosenbrock. `correlated`: the mutations carry n(n-1)/2 rotation
// angles as well as n step sizes (what a curved valley like Rosenbrock's needs; it slows the
// separable functions down).
std::unique_ptr<Problem> make_test_function(const std::string& name, int dimension, bool correlated = false);

}  // namespace mtcs::opt
