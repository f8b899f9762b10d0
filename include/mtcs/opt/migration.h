#pragma once
// The island model's parts that know no molds: each island's own seed, who sends migrants to
// whom, and the ES's side of a migration (the K best leave; arrivals replace the worst when
// better). SMS-EMOA's side is SmsEmoa::emigrants / immigrate. Migration is synchronous: every
// island's emigrants are chosen from the populations before any arrival, so the result depends
// only on the seed and the number of islands, not on threads or processes.

#include <cstdint>
#include <string>
#include <vector>

#include "mtcs/opt/population.h"

namespace mtcs::opt {

enum class Topology { ring, fully_connected };

// "ring" or "fully-connected"; std::invalid_argument otherwise.
Topology parse_topology(const std::string& name);
std::string topology_name(Topology t);

// The seed of island `island` of a run: the run's own seed for island 0 (one island is the plain
// run), a splitmix64 derivation of (seed, island) for the others.
std::uint64_t island_seed(std::uint64_t run_seed, int island);

// The islands `island` receives from, in the order their migrants arrive: ring: the previous
// one; fully connected: every other island, by index.
std::vector<int> migration_sources(Topology t, int islands, int island);

// ES: the k best of a population sorted best first.
std::vector<Individual> best_emigrants(const Generation& g, int k);
// ES: arrivals join the population, which is sorted again (stable: residents before arrivals on
// ties) and cut back to its size: each arrival replaces the worst member when it is better.
Generation replace_worst(const Problem& problem, const Generation& g, const std::vector<Individual>& arrivals);

}  // namespace mtcs::opt
