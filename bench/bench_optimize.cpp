// mtcs bench optimize: optimisers on one mold over several seeds at an equal evaluation budget,
// for the comparisons in experiments/optimize (the algorithms: bench/mold_peers.h).

#include "bench_optimize.h"

#include <filesystem>
#include <iostream>
#include <memory>

#include "mold_peers.h"
#include "mtcs/io/atomic_file.h"
#include "mtcs/mold/layout_io.h"
#include "mtcs/run/session.h"
#include "mtcs/run/shop_layout.h"

namespace mtcs::bench {

int bench_optimize(const OptimizeRuns& oo) {
  const run::Session session(oo.mold, {oo.config, "", {}, std::nullopt, std::nullopt});
  const mold::Scene& scene = session.scene();
  const run::MoldProblem& problem = session.problem();
  // One reference point for every run and algorithm.
  run::RunConfig config = session.config();
  config.algorithm = "sms-emoa";
  if (config.ref.empty()) config.ref = run::scaled_reference(config, problem, scene.spec().objectives);
  const run::MoldOptimizer scaler(problem, scene, config);
  std::cerr << "reference point (scaled):";
  for (const double r : config.ref) std::cerr << ' ' << r;
  std::cerr << '\n';
  auto topology_for = [&](std::uint64_t seed) {
    if (!oo.topology.empty()) return mold::load_layout(oo.topology, scene.spec());
    opt::Rng rng = opt::Rng::for_individual(seed, 0, 0);
    return problem.genome(problem.sample(rng));
  };
  std::unique_ptr<io::AtomicFile> trace;
  if (!oo.trace.empty()) {
    trace = std::make_unique<io::AtomicFile>(oo.trace);
    trace->stream() << "algorithm,seed,evaluations,best_feasible,seconds,hypervolume\n";
  }
  std::cout << "mold,algorithm,seed,evaluations,best_objective,feasible,seconds,hypervolume\n";
  for (const auto& name : oo.algorithms) {
    const std::string algorithm = name == "nlopt" ? "isres" : name;
    for (int seed = 1; seed <= oo.seeds; ++seed) {
      const PeerSetup setup{problem, scene, config, scaler, topology_for(std::uint64_t(seed)), oo.evaluations,
                            std::uint64_t(seed), oo.trace_every > 0 ? oo.trace_every : std::max(1L, oo.evaluations / 100)};
      const PeerResult r = run_mold_algorithm(algorithm, setup);
      std::cout << oo.mold << ',' << name << ',' << seed << ',' << r.evaluations << ',' << r.best.value << ','
                << (r.best.feasible ? 1 : 0) << ',' << r.seconds << ',' << r.hypervolume << std::endl;
      if (!oo.layouts.empty()) {
        std::filesystem::create_directories(oo.layouts);
        // As mtcs optimize writes best.layout.yaml: the drilling plan, rounded for the shop.
        mold::save_layout(oo.layouts + "/" + name + "-seed" + std::to_string(seed) + ".layout.yaml",
                          run::shop_layout(problem, scene, problem.genome(r.best_x)));
      }
      if (trace)
        for (const auto& p : r.trace)
          trace->stream() << name << ',' << seed << ',' << p.evaluations << ',' << p.best_feasible << ',' << p.seconds << ','
                          << p.hypervolume << '\n';
    }
  }
  if (trace) trace->commit();
  return 0;
}

}  // namespace mtcs::bench
