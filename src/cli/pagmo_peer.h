#pragma once
// pagmo 2.18's hypervolume, the peer in benchmarks and a second opinion in tests. Private to the
// cli module: no pagmo or Boost type leaks out.

#include <vector>

namespace mtcs::cli {

double pagmo_hypervolume(const std::vector<std::vector<double>>& points, const std::vector<double>& ref);
std::vector<double> pagmo_contributions(const std::vector<std::vector<double>>& points, const std::vector<double>& ref);

}  // namespace mtcs::cli
