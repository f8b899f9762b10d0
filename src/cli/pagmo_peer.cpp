#include "pagmo_peer.h"

#include <pagmo/utils/hypervolume.hpp>

namespace mtcs::cli {

double pagmo_hypervolume(const std::vector<std::vector<double>>& points, const std::vector<double>& ref) {
  const pagmo::hypervolume hv(points, false);
  return hv.compute(ref);
}

std::vector<double> pagmo_contributions(const std::vector<std::vector<double>>& points, const std::vector<double>& ref) {
  const pagmo::hypervolume hv(points, false);
  return hv.contributions(ref);
}

}  // namespace mtcs::cli
