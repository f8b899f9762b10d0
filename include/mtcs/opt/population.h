#pragma once
// What every optimiser here evolves and stores: individuals (genotype, step sizes, score) and
// generations of them, and the initial population they all start from.

#include <cstdint>
#include <vector>

#include "mtcs/opt/problem.h"

namespace mtcs::opt {

struct Individual {
  Genotype x;
  std::vector<double> steps;
  Score score;
};

struct Generation {
  int index = 0;          // 0: the initial population
  long evaluations = 0;   // spent so far
  // Generations since the best last improved (a restart does not reset it: restarts fire at
  // each multiple of restart_after): the ES's restart on stall decides from it, so the run
  // store keeps it (resume continues the count).
  int stalled = 0;
  std::vector<Individual> population;  // after selection, best first
};

// Evaluates in parallel (TBB); results in input order, whatever the thread count.
std::vector<Score> evaluate_all(const Problem& problem, const std::vector<Genotype>& xs);
// The same with Problem::evaluate_unless_behind(x, bar) for each.
std::vector<Score> evaluate_all(const Problem& problem, const std::vector<Genotype>& xs, const Score& bar);
// The same with Problem::screen.
std::vector<Score> screen_all(const Problem& problem, const std::vector<Genotype>& xs);
// The same with Problem::screen_unless_behind(x, bar) for each.
std::vector<Score> screen_all(const Problem& problem, const std::vector<Genotype>& xs, const Score& bar);
// `count` members evaluated in parallel, in order (unsorted): first the `given` genotypes (a
// user's designs to start from; at most count), then samples, member i drawn from generator i of
// generation 0 (given members take the first generators' places: the samples after them are the
// ones a run without them draws).
Generation sample_population(const Problem& problem, std::uint64_t seed, int count,
                             const std::vector<Genotype>& given = {});

}  // namespace mtcs::opt
