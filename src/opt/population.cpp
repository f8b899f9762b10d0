#include "mtcs/opt/population.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstddef>

#include "mtcs/opt/rng.h"

namespace mtcs::opt {

std::vector<Score> evaluate_all(const Problem& problem, const std::vector<Genotype>& xs) {
  std::vector<Score> scores(xs.size());
  tbb::parallel_for(std::size_t(0), xs.size(), [&](std::size_t i) { scores[i] = problem.evaluate(xs[i]); });
  return scores;
}

std::vector<Score> evaluate_all(const Problem& problem, const std::vector<Genotype>& xs, const Score& bar) {
  std::vector<Score> scores(xs.size());
  tbb::parallel_for(std::size_t(0), xs.size(), [&](std::size_t i) { scores[i] = problem.evaluate_unless_behind(xs[i], bar); });
  return scores;
}

std::vector<Score> screen_all(const Problem& problem, const std::vector<Genotype>& xs) {
  std::vector<Score> scores(xs.size());
  tbb::parallel_for(std::size_t(0), xs.size(), [&](std::size_t i) { scores[i] = problem.screen(xs[i]); });
  return scores;
}

std::vector<Score> screen_all(const Problem& problem, const std::vector<Genotype>& xs, const Score& bar) {
  std::vector<Score> scores(xs.size());
  tbb::parallel_for(std::size_t(0), xs.size(), [&](std::size_t i) { scores[i] = problem.screen_unless_behind(xs[i], bar); });
  return scores;
}

Generation sample_population(const Problem& problem, std::uint64_t seed, int count,
                             const std::vector<Genotype>& given) {
  Generation g;
  std::vector<Genotype> xs(given.begin(), given.begin() + std::min<std::ptrdiff_t>(std::ptrdiff_t(given.size()), count));
  for (int i = int(xs.size()); i < count; ++i) {
    Rng rng = Rng::for_individual(seed, 0, std::uint64_t(i));
    xs.push_back(problem.sample(rng));
  }
  const auto scores = evaluate_all(problem, xs);
  for (std::size_t i = 0; i < xs.size(); ++i) g.population.push_back({xs[i], problem.initial_steps(xs[i]), scores[i]});
  g.evaluations = count;
  return g;
}

}  // namespace mtcs::opt
