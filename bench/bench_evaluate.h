#pragma once
// Throughput of the evaluation pipeline on random layouts (mtcs bench evaluate).

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "mtcs/eval/pipeline.h"
#include "mtcs/mold/genome.h"
#include "mtcs/mold/scene.h"
#include "mtcs/run/mold_problem.h"

namespace mtcs::bench {

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
// Children of mutations: each a mutation (the problem's operators, its rates, the initial step)
// of one of `parents` chosen at random, reproducible from the seed.
std::vector<mold::Genome> mutated_children(const run::MoldProblem& problem, const std::vector<mold::Genome>& parents,
                                           int count, std::uint64_t seed);
// `warm` layouts are evaluated first and not timed (a run's previous generation, or a warm-up).
EvaluateBench bench_evaluate(const eval::Pipeline& pipeline, const std::vector<mold::Genome>& warm,
                             const std::vector<mold::Genome>& genomes, int threads);

// mtcs bench evaluate: one row on one thread and one on `threads`; CSV on stdout, the stages'
// times on stderr.
int bench_evaluate_rows(const std::string& mold_path, int threads, int evaluations, int circuits, int bores,
                        std::uint64_t seed, bool mutations = false, const std::string& config = "");

}  // namespace mtcs::bench
