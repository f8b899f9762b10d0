#include "mtcs/opt/migration.h"

#include <algorithm>
#include <stdexcept>

namespace mtcs::opt {

Topology parse_topology(const std::string& name) {
  if (name == "ring") return Topology::ring;
  if (name == "fully-connected") return Topology::fully_connected;
  throw std::invalid_argument("unknown topology '" + name + "' (ring or fully-connected)");
}

std::string topology_name(Topology t) { return t == Topology::ring ? "ring" : "fully-connected"; }

std::uint64_t island_seed(std::uint64_t run_seed, int island) {
  if (island == 0) return run_seed;
  std::uint64_t z = run_seed ^ (std::uint64_t(island) * 0xd1b54a32d192ed03ULL);
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

std::vector<int> migration_sources(Topology t, int islands, int island) {
  if (islands < 2) return {};
  if (t == Topology::ring) return {(island + islands - 1) % islands};
  std::vector<int> out;
  for (int i = 0; i < islands; ++i)
    if (i != island) out.push_back(i);
  return out;
}

std::vector<Individual> best_emigrants(const Generation& g, int k) {
  const std::size_t n = std::min(g.population.size(), std::size_t(std::max(k, 0)));
  return {g.population.begin(), g.population.begin() + long(n)};
}

Generation replace_worst(const Problem& problem, const Generation& g, const std::vector<Individual>& arrivals) {
  Generation out = g;
  out.population.insert(out.population.end(), arrivals.begin(), arrivals.end());
  std::stable_sort(out.population.begin(), out.population.end(),
                   [&](const Individual& a, const Individual& b) { return problem.better(a.score, b.score); });
  out.population.resize(g.population.size());
  return out;
}

}  // namespace mtcs::opt
