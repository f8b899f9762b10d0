#include "mtcs/run/polish.h"

#include <nlopt.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include "holes.h"
#include "mtcs/io/crash_point.h"

namespace mtcs::run {
namespace {

using geometry::Vec3;

constexpr double kFineStep = 0.05;  // mm: the second round's first moves

// Groups of (circuit, waypoint) sharing one coordinate along one axis.
struct Variable {
  std::size_t circuit;
  int axis;
  std::vector<std::size_t> points;
};

std::vector<Variable> variables_of(const mold::Genome& g, const mold::Scene& scene) {
  const geometry::Box& b = scene.block_bounds();
  const bool aligned = scene.spec().drilling.axis_parallel;
  std::vector<Variable> vars;
  for (std::size_t c = 0; c < g.circuits.size(); ++c) {
    const auto& w = g.circuits[c].waypoints;
    auto on_face = [&](std::size_t p, int k) {
      return (p == 0 || p + 1 == w.size()) && (std::abs(w[p][k] - b.min[k]) < 1e-9 || std::abs(w[p][k] - b.max[k]) < 1e-9);
    };
    for (int k = 0; k < 3; ++k) {
      // Without axis-parallel drilling every waypoint moves on its own.
      std::vector<std::pair<std::size_t, std::size_t>> runs;
      if (aligned) runs = aligned_runs(w, k);
      else
        for (std::size_t i = 0; i < w.size(); ++i) runs.emplace_back(i, i + 1);
      for (const auto& [first, last] : runs) {
        Variable v{c, k, {}};
        bool fixed = false;
        for (std::size_t m = first; m < last; ++m) v.points.push_back(m), fixed = fixed || on_face(m, k);
        if (!fixed) vars.push_back(std::move(v));
      }
    }
  }
  return vars;
}

// Why COBYLA found nothing better, in the designer's words.
std::string why_not_improved(nlopt::result result, const std::string& stopped, const Polished& best, std::size_t coordinates,
                             double first_step, int budget) {
  const std::string moved = std::to_string(coordinates) + " hole coordinates moved by up to " +
                            std::to_string(int(std::lround(first_step))) + " mm";
  if (!best.score.feasible) return "the start violates a constraint and no point COBYLA tried satisfies them all (" + moved + ")";
  if (!stopped.empty()) return "COBYLA stopped: " + stopped + " (" + moved + ")";
  if (result == nlopt::MAXEVAL_REACHED)
    return "the budget of " + std::to_string(budget) + " evaluations ended before COBYLA found a better point or converged (" +
           moved + ")";
  return "the layout is a local optimum for its circuits: " + moved + ", then by up to 0.05 mm, made it no better (COBYLA converged to 0.001 mm)";
}

}  // namespace

Polished polish(const MoldProblem& problem, const mold::Scene& scene, const mold::Genome& start, int max_evaluations) {
  const auto vars = variables_of(start, scene);
  Polished best{start, problem.evaluate(problem.encode(start)), 1, false, ""};
  if (vars.empty()) {
    best.why_not = "no coordinate can move: every hole is held on its face by a port";
    return best;
  }
  if (max_evaluations < 2) {
    best.why_not = "a budget of " + std::to_string(max_evaluations) + " evaluation is too small (at least 2)";
    return best;
  }
  std::vector<double> x, lo, hi;
  for (const auto& v : vars) {
    x.push_back(start.circuits[v.circuit].waypoints[v.points.front()][v.axis]);
    lo.push_back(scene.block_bounds().min[v.axis]);
    hi.push_back(scene.block_bounds().max[v.axis]);
  }
  auto apply = [&](const std::vector<double>& v) {
    mold::Genome g = start;
    for (std::size_t i = 0; i < vars.size(); ++i)
      for (const std::size_t p : vars[i].points) g.circuits[vars[i].circuit].waypoints[p][vars[i].axis] = v[i];
    return g;
  };
  // One evaluation serves the objective and the constraint at the same point.
  struct Ctx {
    std::function<opt::Score(const std::vector<double>&)> score;
  } ctx;
  std::vector<double> last_x, best_point = x;
  opt::Score last;
  ctx.score = [&](const std::vector<double>& v) {
    if (v != last_x) {
      last_x = v;
      const mold::Genome g = apply(v);
      last = problem.evaluate(problem.encode(g));
      ++best.evaluations;
      io::crash_point("polish");
      if (problem.better(last, best.score)) best.genome = g, best.score = last, best.improved = true, best_point = v;
    }
    return last;
  };
  // Two rounds from the best point so far: holes moved by up to half the smallest drill, then
  // by 0.05 mm (five shop tolerances), half of the budget each at most for the first. The first alone improved none of 11 runs on the
  // first-mold part (the ES's best touches a clearance); the fine round improved 2 of 5
  // (experiments/defaults/README.md).
  const double smallest = *std::min_element(scene.spec().drilling.diameters.begin(), scene.spec().drilling.diameters.end());
  std::vector<double> best_x = x;
  nlopt::result result = nlopt::FAILURE;
  std::string stopped;
  for (const double step : {smallest / 2, kFineStep}) {
    // The broad round takes at most half of the budget, the fine one the rest.
    const int left = step == kFineStep ? max_evaluations - (best.evaluations - 1) : max_evaluations / 2;
    if (left < 2) break;
    nlopt::opt solver(nlopt::LN_COBYLA, unsigned(x.size()));
    solver.set_lower_bounds(lo);
    solver.set_upper_bounds(hi);
    solver.set_min_objective(
        [](const std::vector<double>& v, std::vector<double>&, void* d) { return static_cast<Ctx*>(d)->score(v).value; },
        &ctx);
    solver.add_inequality_constraint(
        [](const std::vector<double>& v, std::vector<double>&, void* d) { return static_cast<Ctx*>(d)->score(v).violation; },
        &ctx, 0.0);
    solver.set_initial_step(step);
    solver.set_xtol_abs(1e-3);
    solver.set_maxeval(left);
    x = best_x;
    double f = 0;
    try {
      result = solver.optimize(x, f);
      stopped.clear();
    } catch (const std::exception& e) {
      stopped = e.what();  // round-off or a failure: the best point seen is kept either way
    }
    best_x = best_point;
  }
  if (!best.improved) best.why_not = why_not_improved(result, stopped, best, vars.size(), smallest / 2, max_evaluations);
  return best;
}

}  // namespace mtcs::run
