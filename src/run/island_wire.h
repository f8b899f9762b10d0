#pragma once
// Generations and migrants as bytes, for the messages between MPI ranks: every number as its
// exact bits, so an island run on ranks stores what the same run in threads stores.

#include <string>
#include <vector>

#include "mtcs/opt/population.h"

namespace mtcs::run::wire {

std::string encode(const std::vector<opt::Individual>& individuals);
std::vector<opt::Individual> decode_individuals(const std::string& bytes);
std::string encode(const opt::Generation& g);
opt::Generation decode_generation(const std::string& bytes);
// An island's generations since the last meeting of the islands, in order.
std::string encode(const std::vector<opt::Generation>& generations);
std::vector<opt::Generation> decode_generations(const std::string& bytes);

}  // namespace mtcs::run::wire
