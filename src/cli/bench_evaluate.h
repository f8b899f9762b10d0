#pragma once
// Throughput of the evaluation pipeline on random layouts (mtcs bench evaluate).

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "mtcs/mold/genome.h"
#include "mtcs/mold/scene.h"

namespace mtcs::cli {

struct EvaluateBench {
  int bores = 0;
  std::size_t samples = 0;
  double evaluations_per_second = 0;
  std::map<std::string, double> stage_seconds;  // mean per evaluation
};

// `count` layouts of `circuits` circuits of `bores` axis-parallel legs each (one more where the
// drillable axes force an odd count), reproducible from the seed.
std::vector<mold::Genome> random_genomes(const mold::Scene& scene, int count, int circuits, int bores,
                                         std::uint64_t seed);
EvaluateBench bench_evaluate(const mold::Scene& scene, const std::vector<mold::Genome>& genomes, int threads);

}  // namespace mtcs::cli
