#pragma once
// `mtcs optimize --problem NAME`: SMS-EMOA on a built-in multi-objective test problem (ZDT,
// DTLZ), with the population stored every mu steps when a store is given.

#include <cstdint>
#include <string>
#include <vector>

#include "mtcs/opt/problem.h"

namespace mtcs::run {

struct TestProblemRun {
  std::string problem;
  std::uint64_t seed = 1;
  long evaluations = 0;      // spent
  double hypervolume = 0;    // of the final front against ref
  std::vector<double> ref;   // the reference point used
  std::size_t front_size = 0;
  double seconds = 0;
};

// The reference point a test problem is measured against by default: 1.1 per objective.
std::vector<double> default_test_reference(const std::string& problem);

// `problem` is opt::make_benchmark_problem(name); `ref` has one value per objective
// (default_test_reference's size). `store_path` empty: nothing stored.
TestProblemRun run_test_problem(const opt::Problem& problem, const std::string& name, std::uint64_t seed,
                                long evaluations, const std::vector<double>& ref, const std::string& store_path);

// The run as one JSON object (problem, algorithm, seed, evaluations, hypervolume,
// reference_point, front_size, seconds): indented, or on one line when `one_line`.
std::string to_json(const TestProblemRun& run, bool one_line);

}  // namespace mtcs::run
