#include "mtcs/run/test_problem_run.h"

#include <chrono>
#include <nlohmann/json.hpp>
#include <optional>

#include "mtcs/opt/benchmark_problems.h"
#include "mtcs/opt/hypervolume.h"
#include "mtcs/opt/sms_emoa.h"
#include "mtcs/store/run_store.h"
#include "mtcs/version.h"

namespace mtcs::run {

std::vector<double> default_test_reference(const std::string& problem) {
  return std::vector<double>(std::size_t(opt::objective_count(problem)), 1.1);
}

TestProblemRun run_test_problem(const opt::Problem& problem, const std::string& name, std::uint64_t seed,
                                long evaluations, const std::vector<double>& ref,
                                const std::string& store_path) {
  opt::SmsConfig c;
  c.seed = seed;
  c.evaluations = evaluations;
  c.ref = ref;
  std::optional<store::RunStore> db;
  if (!store_path.empty())
    db = store::RunStore::create(store_path, {{"problem", name},
                                              {"algorithm", "sms-emoa"},
                                              {"seed", std::to_string(seed)},
                                              {"program", kProgram}});
  const opt::SmsEmoa sms(problem, c);
  const auto t0 = std::chrono::steady_clock::now();
  auto since_start = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };
  const opt::Generation last = opt::run(sms, nullptr, [&](const opt::Generation& g) {
    if (db && g.index % c.mu == 0) db->save(g, since_start());
  });
  if (db) db->commit();
  const double seconds = since_start();
  const auto front = opt::SmsEmoa::front(last);
  return {name, seed, last.evaluations, opt::hypervolume(front, c.ref), c.ref, front.size(), seconds};
}

std::string to_json(const TestProblemRun& r, bool one_line) {
  const nlohmann::ordered_json j{{"problem", r.problem},         {"algorithm", "sms-emoa"},  {"seed", r.seed},
                                 {"evaluations", r.evaluations}, {"hypervolume", r.hypervolume},
                                 {"reference_point", r.ref},     {"front_size", r.front_size}, {"seconds", r.seconds}};
  return one_line ? j.dump() : j.dump(2);
}

}  // namespace mtcs::run
