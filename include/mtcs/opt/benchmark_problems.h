#pragma once
// Multi-objective test problems (minimisation): ZDT1-4, ZDT6 (Zitzler, Deb & Thiele 2000;
// n = 30, 30, 30, 10, 10) and DTLZ1-7 with 3 objectives (Deb, Thiele, Laumanns & Zitzler 2002;
// k = 5 for DTLZ1, 20 for DTLZ7, 10 otherwise). Variation as in Deb's settings: simulated binary
// crossover (eta 15) and polynomial mutation (eta 20, rate 1/n).

#include <memory>
#include <string>

#include "mtcs/opt/problem.h"

namespace mtcs::opt {

// name: zdt1, zdt2, zdt3, zdt4, zdt6, dtlz1 ... dtlz7. Throws std::invalid_argument otherwise.
std::unique_ptr<Problem> make_benchmark_problem(const std::string& name);
int objective_count(const std::string& name);

}  // namespace mtcs::opt
