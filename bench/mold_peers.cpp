// mtcs bench optimize's algorithms on a mold. mtcs's own run on the mold problem; the peers
// search the waypoint coordinates of a fixed topology (ports stay on their faces), scaled to the
// unit box. Constraints: ISRES handles them natively (stochastic ranking); CRS2, CMA-ES, NSGA-II
// and MOEA/D see 1e6 + violation for an infeasible layout (each objective), which ranks layouts
// as constrained domination does: feasible first, then by violation.

#include "mold_peers.h"
#include "mtcs/opt/forwarding_problem.h"

#include <nlopt.hpp>
#include <pagmo/algorithm.hpp>
#include <pagmo/algorithms/cmaes.hpp>
#include <pagmo/algorithms/moead.hpp>
#include <pagmo/algorithms/nsga2.hpp>
#include <pagmo/population.hpp>
#include <pagmo/problem.hpp>

#include <chrono>
#include <cmath>
#include <limits>
#include <mutex>
#include <stdexcept>

#include "mtcs/opt/sms_emoa.h"

namespace mtcs::bench {
namespace {

using Clock = std::chrono::steady_clock;
constexpr double kInfeasible = 1e6;  // below it every feasible layout, above it the violation

// Every evaluation of the run: mtcs's optimisers evaluate through it as a Problem, the peers
// through FixedTopology. Thread-safe (the ES evaluates in parallel).
class Recorder final : public opt::ForwardingProblem {
 public:
  Recorder(const run::MoldProblem& inner, const run::MoldOptimizer& scaler, long every)
      : ForwardingProblem(inner), scaler_(scaler), every_(std::max(1L, every)), start_(Clock::now()) {
    best_.feasible = false;
    best_.violation = best_.value = std::numeric_limits<double>::infinity();
  }

  opt::Score evaluate(const opt::Genotype& g) const override {
    opt::Score s = inner_.evaluate(g);
    record(s, g);
    return s;
  }
  // A layout scored without its objectives is infeasible behind a feasible bar: never the best,
  // never in the (feasible) archive.
  opt::Score evaluate_unless_behind(const opt::Genotype& g, const opt::Score& bar) const override {
    opt::Score s = inner_.evaluate_unless_behind(g, bar);
    record(s, g);
    return s;
  }

  long evaluations() const {
    const std::lock_guard<std::mutex> hold(lock_);
    return count_;
  }
  PeerResult finish() const {
    const std::lock_guard<std::mutex> hold(lock_);
    PeerResult r{best_, best_x_, scaler_.scaled_hypervolume(archive_), count_, seconds(), trace_};
    if (r.trace.empty() || r.trace.back().evaluations != count_) r.trace.push_back(point());
    return r;
  }

 private:
  double seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }
  AnytimePoint point() const {
    return {count_, seconds(), best_.feasible ? best_.value : std::numeric_limits<double>::infinity(),
            scaler_.scaled_hypervolume(archive_)};
  }
  static bool dominates(const opt::Point& a, const opt::Point& b) {
    bool strictly = false;
    for (std::size_t k = 0; k < a.size(); ++k) {
      if (a[k] > b[k]) return false;
      strictly = strictly || a[k] < b[k];
    }
    return strictly;
  }
  void record(const opt::Score& s, const opt::Genotype& g) const {
    const std::lock_guard<std::mutex> hold(lock_);
    ++count_;
    if (inner_.better(s, best_)) best_ = s, best_x_ = g;
    if (s.feasible) {
      bool covered = false;
      for (const auto& a : archive_)
        if (a == s.objectives || dominates(a, s.objectives)) {
          covered = true;
          break;
        }
      if (!covered) {
        std::erase_if(archive_, [&](const opt::Point& a) { return dominates(s.objectives, a); });
        archive_.push_back(s.objectives);
      }
    }
    if (count_ % every_ == 0) trace_.push_back(point());
  }

  const run::MoldOptimizer& scaler_;
  long every_;
  Clock::time_point start_;
  mutable std::mutex lock_;
  mutable long count_ = 0;
  mutable opt::Score best_;
  mutable opt::Genotype best_x_;
  mutable std::vector<opt::Point> archive_;  // feasible, non-dominated
  mutable std::vector<AnytimePoint> trace_;
};

// The coordinates a fixed-topology peer moves, in the unit box: all of interior waypoints, the
// two in-face ones of ports.
class FixedTopology {
 public:
  FixedTopology(const Recorder& recorder, const run::MoldProblem& problem, const mold::Scene& scene, mold::Genome topology)
      : recorder_(recorder), problem_(problem), topology_(std::move(topology)), box_(scene.block_bounds()) {
    for (std::size_t c = 0; c < topology_.circuits.size(); ++c) {
      const auto& w = topology_.circuits[c].waypoints;
      for (std::size_t p = 0; p < w.size(); ++p) {
        int fixed = -1;
        if (p == 0 || p + 1 == w.size())
          for (int k = 0; k < 3; ++k)
            if (std::abs(w[p][k] - box_.min[k]) < 1e-9 || std::abs(w[p][k] - box_.max[k]) < 1e-9) fixed = k;
        for (int k = 0; k < 3; ++k)
          if (k != fixed) slots_.push_back({c, p, k});
      }
    }
  }
  std::size_t size() const { return slots_.size(); }
  long evaluations() const { return recorder_.evaluations(); }
  std::vector<double> start() const {
    std::vector<double> u;
    for (const auto& s : slots_)
      u.push_back((topology_.circuits[s.circuit].waypoints[s.point][s.axis] - box_.min[s.axis]) /
                  (box_.max[s.axis] - box_.min[s.axis]));
    return u;
  }
  opt::Score score(const std::vector<double>& u) const {
    mold::Genome g = topology_;
    for (std::size_t i = 0; i < slots_.size(); ++i) {
      const auto& s = slots_[i];
      g.circuits[s.circuit].waypoints[s.point][s.axis] =
          box_.min[s.axis] + std::clamp(u[i], 0.0, 1.0) * (box_.max[s.axis] - box_.min[s.axis]);
    }
    return recorder_.evaluate(problem_.encode(g));
  }
  static double penalised(const opt::Score& s) { return s.feasible ? s.value : kInfeasible + s.violation; }

 private:
  struct Slot {
    std::size_t circuit, point;
    int axis;
  };
  const Recorder& recorder_;
  const run::MoldProblem& problem_;
  mold::Genome topology_;
  geometry::Box box_;
  std::vector<Slot> slots_;
};

// pagmo's user-defined problem: the fixed topology's unit box; one objective (the weighted one)
// or the mold's objectives in scaled units.
struct MoldUdp {
  const FixedTopology* coords = nullptr;
  const std::vector<double>* scales = nullptr;
  unsigned objectives = 1;
  std::vector<double> fitness(const std::vector<double>& u) const {
    const opt::Score s = coords->score(u);
    if (objectives == 1) return {FixedTopology::penalised(s)};
    std::vector<double> f(objectives, kInfeasible + s.violation);
    if (s.feasible)
      for (unsigned k = 0; k < objectives; ++k) f[k] = s.objectives[k] / (*scales)[k];
    return f;
  }
  std::pair<std::vector<double>, std::vector<double>> get_bounds() const {
    return {std::vector<double>(coords->size(), 0.0), std::vector<double>(coords->size(), 1.0)};
  }
  pagmo::vector_double::size_type get_nobj() const { return objectives; }
};

void run_pagmo(const std::string& algorithm, const FixedTopology& coords, const run::MoldOptimizer& scaler, long budget,
               unsigned seed) {
  MoldUdp udp{&coords, &scaler.scales(), algorithm == "cmaes" ? 1u : unsigned(scaler.scales().size())};
  const pagmo::problem prob{udp};
  // CMA-ES: its default lambda = 4 + 3 ln n; NSGA-II and MOEA/D: 100, as on ZDT/DTLZ.
  const unsigned pop_size =
      algorithm == "cmaes" ? unsigned(4 + std::floor(3 * std::log(double(coords.size())))) : 100u;
  const unsigned generations = unsigned(std::max<long>(1, (budget - pop_size) / pop_size));
  pagmo::algorithm algo;
  if (algorithm == "nsga2") algo = pagmo::algorithm{pagmo::nsga2(generations, 0.9, 20., 1. / double(coords.size()), 20., seed)};
  else if (algorithm == "moead")
    algo = pagmo::algorithm{pagmo::moead(generations, "low discrepancy", "tchebycheff", 20u, 1.0, 0.5, 20., 0.9, 2u, true, seed)};
  else algo = pagmo::algorithm{pagmo::cmaes(generations, -1, -1, -1, -1, 0.3, 0.0, 0.0, false, true, seed)};
  pagmo::population pop{prob, pop_size - 1, seed};
  pop.push_back(coords.start());  // the topology's own layout, as ISRES and CRS2 start from it
  algo.evolve(pop);
}

void run_nlopt(const std::string& algorithm, const FixedTopology& coords, long budget, std::uint64_t seed) {
  std::vector<double> x = coords.start();
  // One evaluation serves ISRES's objective and constraint: remember the last.
  std::vector<double> last_x;
  opt::Score last;
  auto score_of = [&](const std::vector<double>& v) -> const opt::Score& {
    if (v != last_x) {
      // CRS2 may ask a few points past maxeval: the budget is the same for every algorithm.
      if (coords.evaluations() >= budget) throw nlopt::forced_stop();
      last_x = v, last = coords.score(v);
    }
    return last;
  };
  using ScoreOf = decltype(score_of);
  nlopt::srand(seed);
  const bool isres = algorithm == "isres";
  nlopt::opt solver(isres ? nlopt::GN_ISRES : nlopt::GN_CRS2_LM, unsigned(x.size()));
  solver.set_lower_bounds(std::vector<double>(x.size(), 0.0));
  solver.set_upper_bounds(std::vector<double>(x.size(), 1.0));
  if (isres) {
    solver.set_min_objective([](const std::vector<double>& v, std::vector<double>&, void* d) { return (*static_cast<ScoreOf*>(d))(v).value; },
                             &score_of);
    solver.add_inequality_constraint(
        [](const std::vector<double>& v, std::vector<double>&, void* d) { return (*static_cast<ScoreOf*>(d))(v).violation; },
        &score_of, 0.0);
  } else {
    solver.set_min_objective(
        [](const std::vector<double>& v, std::vector<double>&, void* d) { return FixedTopology::penalised((*static_cast<ScoreOf*>(d))(v)); },
        &score_of);
  }
  solver.set_maxeval(int(budget));
  double f = 0;
  try {
    solver.optimize(x, f);
  } catch (const std::exception&) {
    // Stopped on its budget or round-off; the recorder kept the best layout either way.
  }
}

}  // namespace

PeerResult run_mold_algorithm(const std::string& algorithm, const PeerSetup& s) {
  const Recorder recorder(s.problem, s.scaler, s.trace_every);
  if (algorithm == "es" || algorithm == "random") {
    opt::EsConfig es = s.config.es;
    es.seed = s.seed;
    es.evaluations = s.evaluations;
    es.random_search = algorithm == "random";
    const auto& d = s.scene.spec().drilling.diameters;
    es.min_step = 0.1 * *std::min_element(d.begin(), d.end());
    opt::run(opt::EvolutionStrategy(recorder, es), nullptr, {});
  } else if (algorithm == "sms-emoa") {
    opt::SmsConfig c;
    c.mu = s.config.es.mu;
    c.seed = s.seed;
    c.evaluations = s.evaluations;
    c.ref = s.scaler.raw_reference();
    opt::run(opt::SmsEmoa(recorder, c), nullptr, {});
  } else {
    const FixedTopology coords(recorder, s.problem, s.scene, s.topology);
    if (algorithm == "isres" || algorithm == "crs2") run_nlopt(algorithm, coords, s.evaluations, s.seed);
    else if (algorithm == "cmaes" || algorithm == "nsga2" || algorithm == "moead")
      run_pagmo(algorithm, coords, s.scaler, s.evaluations, unsigned(s.seed));
    else throw std::invalid_argument("unknown algorithm " + algorithm);
  }
  return recorder.finish();
}

}  // namespace mtcs::bench
