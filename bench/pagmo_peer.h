#pragma once
// pagmo 2.18's hypervolume, the peer in benchmarks and a second opinion in tests. Private to the
// cli module: no pagmo or Boost type leaks out.

#include <string>
#include <vector>

namespace mtcs::bench {

double pagmo_hypervolume(const std::vector<std::vector<double>>& points, const std::vector<double>& ref);
std::vector<double> pagmo_contributions(const std::vector<std::vector<double>>& points, const std::vector<double>& ref);

}  // namespace mtcs::bench

namespace mtcs::bench {

// pagmo's NSGA-II (Deb's settings: crossover 0.9, eta_c 20, mutation 1/n, eta_m 20) or MOEA/D
// (grid weights for 2 objectives, low-discrepancy for 3; Tchebycheff) on pagmo's own ZDT/DTLZ, population 100: the final objective
// vectors. name: zdt1..zdt6, dtlz1..dtlz7; algorithm: nsga2, moead.
std::vector<std::vector<double>> pagmo_run(const std::string& name, const std::string& algorithm, long evaluations,
                                           unsigned seed);

}  // namespace mtcs::bench
