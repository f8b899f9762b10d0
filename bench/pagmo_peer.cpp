#include "pagmo_peer.h"

#include <pagmo/utils/hypervolume.hpp>

namespace mtcs::bench {

double pagmo_hypervolume(const std::vector<std::vector<double>>& points, const std::vector<double>& ref) {
  const pagmo::hypervolume hv(points, false);
  return hv.compute(ref);
}

std::vector<double> pagmo_contributions(const std::vector<std::vector<double>>& points, const std::vector<double>& ref) {
  const pagmo::hypervolume hv(points, false);
  return hv.contributions(ref);
}

}  // namespace mtcs::bench

#include <pagmo/algorithm.hpp>
#include <pagmo/algorithms/moead.hpp>
#include <pagmo/algorithms/nsga2.hpp>
#include <pagmo/population.hpp>
#include <pagmo/problem.hpp>
#include <pagmo/problems/dtlz.hpp>
#include <pagmo/problems/zdt.hpp>

namespace mtcs::bench {

std::vector<std::vector<double>> pagmo_run(const std::string& name, const std::string& algorithm, long evaluations,
                                           unsigned seed) {
  const unsigned id = unsigned(name.back() - '0');
  pagmo::problem prob;
  if (name.rfind("zdt", 0) == 0) prob = pagmo::problem{pagmo::zdt(id, id == 4 || id == 6 ? 10u : 30u)};
  else prob = pagmo::problem{pagmo::dtlz(id, id == 1 ? 7u : (id == 7 ? 22u : 12u), 3u)};
  const unsigned pop_size = 100;
  const unsigned generations = unsigned(std::max<long>(1, (evaluations - pop_size) / pop_size));
  const double n = double(prob.get_nx());
  pagmo::algorithm algo = algorithm == "nsga2" ? pagmo::algorithm{pagmo::nsga2(generations, 0.9, 20., 1. / n, 20., seed)}
                                               : pagmo::algorithm{pagmo::moead(generations, prob.get_nobj() == 2 ? "grid" : "low discrepancy", "tchebycheff", 20u,
                                                                               1.0, 0.5, 20., 0.9, 2u, true, seed)};
  pagmo::population pop{prob, pop_size, seed};
  pop = algo.evolve(pop);
  return pop.get_f();
}

}  // namespace mtcs::bench
