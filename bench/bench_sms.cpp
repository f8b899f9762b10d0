// mtcs bench sms-emoa: our SMS-EMOA against pagmo's NSGA-II and MOEA/D on ZDT/DTLZ, same budgets
// and seeds, hypervolume of each final non-dominated set against (1.1, ..., 1.1); wall and CPU
// seconds (the CPU time, of all threads, is what a loaded machine leaves comparable).

#include <chrono>
#include <ctime>
#include <iostream>

#include "bench_sms.h"
#include "mtcs/opt/benchmark_problems.h"
#include "mtcs/opt/sms_emoa.h"
#include "pagmo_peer.h"

namespace mtcs::bench {
namespace {

bool dominates(const std::vector<double>& a, const std::vector<double>& b) {
  bool strictly = false;
  for (std::size_t k = 0; k < a.size(); ++k) {
    if (a[k] > b[k]) return false;
    strictly = strictly || a[k] < b[k];
  }
  return strictly;
}

std::vector<std::vector<double>> nondominated(const std::vector<std::vector<double>>& f) {
  std::vector<std::vector<double>> out;
  for (std::size_t i = 0; i < f.size(); ++i) {
    bool dom = false;
    for (std::size_t j = 0; j < f.size() && !dom; ++j) dom = j != i && dominates(f[j], f[i]);
    if (!dom) out.push_back(f[i]);
  }
  return out;
}

}  // namespace

int bench_sms(const std::string& problem, const std::vector<std::string>& algorithms, int seeds, long evaluations) {
  const std::vector<double> ref(std::size_t(opt::objective_count(problem)), 1.1);
  std::cout << "problem,algorithm,seed,evaluations,hypervolume,seconds,cpu_seconds" << std::endl;
  for (const auto& algorithm : algorithms) {
    for (int seed = 1; seed <= seeds; ++seed) {
      const auto t0 = std::chrono::steady_clock::now();
      const std::clock_t c0 = std::clock();
      std::vector<std::vector<double>> front;
      if (algorithm == "sms-emoa") {
        const auto p = opt::make_benchmark_problem(problem);
        opt::SmsConfig c;
        c.seed = std::uint64_t(seed);
        c.evaluations = evaluations;
        c.ref = ref;
        front = opt::SmsEmoa::front(opt::run(opt::SmsEmoa(*p, c), nullptr, {}));
      } else {
        front = nondominated(pagmo_run(problem, algorithm, evaluations, unsigned(seed)));
      }
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      const double cpu = double(std::clock() - c0) / CLOCKS_PER_SEC;  // all threads: load-independent
      std::cout << problem << ',' << algorithm << ',' << seed << ',' << evaluations << ','
                << opt::hypervolume(front, ref) << ',' << seconds << ',' << cpu << std::endl;
    }
  }
  return 0;
}

}  // namespace mtcs::bench
