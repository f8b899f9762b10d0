// mtcs bench optimize: one optimiser on one mold over several seeds at an equal evaluation
// budget, for the comparisons in experiments/optimize: the ES, random search (the same machinery
// with fresh samples as offspring), and NLopt's ISRES on the coordinates of a fixed topology.

#include <nlopt.hpp>

#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>

#include "bench_optimize.h"
#include "mtcs/io/atomic_file.h"
#include "mtcs/run/session.h"
#include "mtcs/mold/layout_io.h"

namespace mtcs::bench {
namespace {

using geometry::Vec3;

// The coordinates NLopt may move: all of interior waypoints, the two in-face ones of ports.
struct Coordinates {
  struct Slot {
    std::size_t circuit, point;
    int axis;
  };
  std::vector<Slot> slots;

  Coordinates(const mold::Genome& g, const mold::Scene& scene) {
    const geometry::Box& b = scene.block_bounds();
    for (std::size_t c = 0; c < g.circuits.size(); ++c) {
      const auto& w = g.circuits[c].waypoints;
      for (std::size_t p = 0; p < w.size(); ++p) {
        int fixed = -1;
        if (p == 0 || p + 1 == w.size()) {  // a port: keep the coordinate that puts it on its face
          for (int k = 0; k < 3; ++k)
            if (std::abs(w[p][k] - b.min[k]) < 1e-9 || std::abs(w[p][k] - b.max[k]) < 1e-9) fixed = k;
        }
        for (int k = 0; k < 3; ++k)
          if (k != fixed) slots.push_back({c, p, k});
      }
    }
  }
  mold::Genome apply(mold::Genome g, const std::vector<double>& x) const {
    for (std::size_t i = 0; i < slots.size(); ++i) g.circuits[slots[i].circuit].waypoints[slots[i].point][slots[i].axis] = x[i];
    return g;
  }
};

}  // namespace

OptimizeTrace bench_es(const MoldProblem& problem, opt::EsConfig config) {
  const auto t0 = std::chrono::steady_clock::now();
  OptimizeTrace trace;
  const opt::EvolutionStrategy es(problem, config);
  const opt::Generation last = opt::run(es, nullptr, [&](const opt::Generation& g) {
    const auto& best = g.population.front().score;
    trace.points.push_back({g.evaluations, best.feasible ? best.value : std::numeric_limits<double>::infinity()});
  });
  trace.best = last.population.front().score;
  trace.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return trace;
}

OptimizeTrace bench_nlopt(const MoldProblem& problem, const mold::Scene& scene, const mold::Genome& topology,
                          long evaluations, std::uint64_t seed) {
  const auto t0 = std::chrono::steady_clock::now();
  const Coordinates coords(topology, scene);
  std::vector<double> x, lo, hi;
  for (const auto& s : coords.slots) {
    x.push_back(topology.circuits[s.circuit].waypoints[s.point][s.axis]);
    lo.push_back(scene.block_bounds().min[s.axis]);
    hi.push_back(scene.block_bounds().max[s.axis]);
  }
  OptimizeTrace trace;
  trace.best.feasible = false;
  trace.best.violation = std::numeric_limits<double>::infinity();
  trace.best.value = std::numeric_limits<double>::infinity();
  long count = 0;
  // One evaluation serves the objective and the constraint: remember the last.
  std::vector<double> last_x;
  opt::Score last_score;
  auto score_of = [&](const std::vector<double>& v) {
    if (v != last_x) {
      last_x = v;
      last_score = problem.evaluate(problem.encode(coords.apply(topology, v)));
      ++count;
      if (problem.better(last_score, trace.best)) trace.best = last_score;
      trace.points.push_back({count, trace.best.feasible ? trace.best.value : std::numeric_limits<double>::infinity()});
    }
    return last_score;
  };
  struct Ctx {
    decltype(score_of)* score;
  } ctx{&score_of};
  nlopt::srand(seed);
  nlopt::opt solver(nlopt::GN_ISRES, unsigned(x.size()));
  solver.set_lower_bounds(lo);
  solver.set_upper_bounds(hi);
  solver.set_min_objective(
      [](const std::vector<double>& v, std::vector<double>&, void* d) {
        return (*static_cast<Ctx*>(d)->score)(v).value;
      },
      &ctx);
  solver.add_inequality_constraint(
      [](const std::vector<double>& v, std::vector<double>&, void* d) {
        return (*static_cast<Ctx*>(d)->score)(v).violation;
      },
      &ctx, 0.0);
  solver.set_maxeval(int(evaluations));
  double f = 0;
  try {
    solver.optimize(x, f);
  } catch (const std::exception&) {
    // ISRES stops on its budget or round-off; the best point seen is kept either way.
  }
  trace.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return trace;
}

int bench_optimize(const OptimizeRuns& oo) {
  const run::Session session(oo.mold, {oo.config, "", {}, std::nullopt, std::nullopt});
  const mold::Scene& scene = session.scene();
  const run::RunConfig& config = session.config();
  const MoldProblem& problem = session.problem();
  // NLopt's fixed topology: a layout file, or by default the seed's first random sample (the
  // same kind of start the ES gets).
  auto topology_for = [&](std::uint64_t seed) {
    if (!oo.topology.empty()) return mold::load_layout(oo.topology, scene.spec());
    opt::Rng rng = opt::Rng::for_individual(seed, 0, 0);
    return problem.genome(problem.sample(rng));
  };
  std::unique_ptr<io::AtomicFile> trace;
  if (!oo.trace.empty()) {
    trace = std::make_unique<io::AtomicFile>(oo.trace);
    trace->stream() << "algorithm,seed,evaluations,best_feasible\n";
  }
  std::cout << "mold,algorithm,seed,evaluations,best_objective,feasible,seconds\n";
  for (int seed = 1; seed <= oo.seeds; ++seed) {
    OptimizeTrace t;
    if (oo.algorithm == "nlopt") {
      t = bench_nlopt(problem, scene, topology_for(std::uint64_t(seed)), oo.evaluations, std::uint64_t(seed));
    } else {
      opt::EsConfig es = config.es;
      es.seed = std::uint64_t(seed);
      es.evaluations = oo.evaluations;
      es.random_search = oo.algorithm == "random";
      es.min_step = 0.1 * *std::min_element(scene.spec().drilling.diameters.begin(), scene.spec().drilling.diameters.end());
      t = bench_es(problem, es);
    }
    std::cout << oo.mold << ',' << oo.algorithm << ',' << seed << ',' << oo.evaluations << ',' << t.best.value << ','
              << (t.best.feasible ? 1 : 0) << ',' << t.seconds << std::endl;
    if (trace)
      for (const auto& p : t.points)
        trace->stream() << oo.algorithm << ',' << seed << ',' << p.evaluations << ',' << p.best_feasible << '\n';
  }
  if (trace) trace->commit();
  return 0;
}

}  // namespace mtcs::bench
