// mtcs bench evaluate: evaluations per second on random layouts of a mold, on one thread and on
// N threads (TBB), with the time split by stage.

#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <map>
#include <stdexcept>

#include "bench_evaluate.h"
#include "mtcs/eval/pipeline.h"
#include "mtcs/mold/decoder.h"
#include "mtcs/opt/rng.h"
#include "mtcs/run/session.h"

namespace mtcs::bench {
namespace {

using geometry::Vec3;

using mold::axis_of;

// A circuit of `bores` axis-parallel legs from an inlet face to an outlet face; coordinates
// uniform in the block's inner 80%.
mold::Circuit random_circuit(const mold::Scene& scene, opt::Rng& rng, int bores, double diameter) {
  const auto& spec = scene.spec();
  const geometry::Box& b = scene.block_bounds();
  const Vec3 lo = b.min + 0.1 * b.size(), hi = b.max - 0.1 * b.size();
  auto inside = [&](int k) { return lo[k] + rng.uniform() * (hi[k] - lo[k]); };
  auto on_face = [&](mold::Face f) {
    Vec3 p(inside(0), inside(1), inside(2));
    p[axis_of(f)] = mold::face_plane(b, f);
    return p;
  };
  const mold::Face in = spec.circuits.inlet_faces[std::size_t(rng.below(int(spec.circuits.inlet_faces.size())))];
  const mold::Face out = spec.circuits.outlet_faces[std::size_t(rng.below(int(spec.circuits.outlet_faces.size())))];
  mold::Circuit c;
  c.diameter = diameter;
  Vec3 p = on_face(in);
  c.waypoints.push_back(p);
  int prev = axis_of(in);
  p[prev] = inside(prev);  // first leg: straight in from the inlet face
  c.waypoints.push_back(p);
  // Legs along drillable axes only (the decoder keeps a circuit in its inlet's plane along the
  // others), never twice along one axis in a row. With two drillable axes a path between faces
  // of the same axis needs an odd number of legs: an even request gets one more.
  std::vector<int> axes;
  for (const mold::Face f : spec.drilling.allowed_faces)
    if (std::find(axes.begin(), axes.end(), axis_of(f)) == axes.end()) axes.push_back(axis_of(f));
  if (axes.size() < 2) {  // one drillable axis (the reference block): a straight bore through
    if (axis_of(out) != axis_of(in) || out == in)
      throw std::runtime_error("random layouts: one drillable axis needs the inlet and outlet on its two opposite faces");
    p[axis_of(out)] = mold::face_plane(b, out);
    c.waypoints.back() = p;
    return c;
  }
  for (int leg = 1; leg + 1 < bores; ++leg) {
    std::vector<int> choice;
    for (const int k : axes)
      if (k != prev && (leg + 2 != bores || k != axis_of(out))) choice.push_back(k);
    if (choice.empty()) {  // parity: only the outlet's axis is left
      ++bores;
      for (const int k : axes)
        if (k != prev) choice.push_back(k);
    }
    const int k = choice[std::size_t(rng.below(int(choice.size())))];
    p[k] = inside(k);
    c.waypoints.push_back(p);
    prev = k;
  }
  const int k = axis_of(out);
  p[k] = mold::normal_of(out)[k] > 0 ? b.max[k] : b.min[k];
  c.waypoints.push_back(p);
  return c;
}

}  // namespace

std::vector<mold::Genome> random_genomes(const mold::Scene& scene, int count, int circuits, int bores,
                                         std::uint64_t seed) {
  opt::Rng rng(seed);  // the optimisers' generator: the same layouts on every platform
  const auto& diameters = scene.spec().drilling.diameters;
  std::vector<mold::Genome> out(static_cast<std::size_t>(count));
  for (auto& g : out)
    for (int c = 0; c < circuits; ++c)
      g.circuits.push_back(random_circuit(scene, rng, bores, diameters[std::size_t(rng.below(int(diameters.size())))]));
  return out;
}

std::vector<mold::Genome> mutated_children(const run::MoldProblem& problem, const std::vector<mold::Genome>& parents,
                                           int count, std::uint64_t seed) {
  opt::Rng rng(seed);
  std::vector<mold::Genome> out(static_cast<std::size_t>(count));
  for (auto& child : out) {
    opt::Genotype x = problem.encode(parents[std::size_t(rng.below(int(parents.size())))]);
    problem.mutate(x, problem.initial_steps(x), rng);
    child = problem.genome(x);
  }
  return out;
}

EvaluateBench bench_evaluate(const eval::Pipeline& pipeline, const std::vector<mold::Genome>& warm,
                             const std::vector<mold::Genome>& genomes, int threads) {
  const mold::Scene& scene = pipeline.scene();
  EvaluateBench r;
  r.samples = pipeline.surface_samples();
  r.bores = 0;
  for (const auto& c : genomes.front().circuits) r.bores += int(mold::routed_waypoints(scene, c).size()) - 1;
  std::vector<double> sink(std::max(genomes.size(), warm.size()));
  const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
  tbb::parallel_for(std::size_t(0), warm.size(), [&](std::size_t i) { sink[i] = pipeline.evaluate(warm[i]).violation; });
  const auto t0 = std::chrono::steady_clock::now();
  tbb::parallel_for(std::size_t(0), genomes.size(),
                    [&](std::size_t i) { sink[i] = pipeline.evaluate(genomes[i]).violation; });
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.evaluations_per_second = double(genomes.size()) / seconds;
  return r;
}

// The split by stage, on one thread, over `genomes` (after `warm`, as the timed row).
std::map<std::string, double> stage_split(const eval::Pipeline& pipeline, const std::vector<mold::Genome>& warm,
                                          const std::vector<mold::Genome>& genomes) {
  std::map<std::string, double> split;
  for (const auto& g : warm) pipeline.evaluate(g);
  for (const auto& g : genomes)
    for (const auto& s : pipeline.evaluate(g, true).stages) split[s.name] += s.seconds / double(genomes.size());
  return split;
}

int bench_evaluate_rows(const std::string& mold_path, int threads, int evaluations, int circuits, int bores,
                        std::uint64_t seed, bool mutations, const std::string& config) {
  run::RunOverrides overrides;
  overrides.config = config;
  const run::Session session(mold_path, overrides);
  const mold::Scene& scene = session.scene();
  // Every pass gets layouts no earlier pass evaluated: the stages' caches start as cold for
  // random layouts as in a run, and hold the parents for children.
  const int rows = threads > 1 ? 2 : 1, split = std::min(evaluations, 500);
  const int parents = 15;  // the default ES's mu
  std::vector<mold::Genome> all = random_genomes(scene, mutations ? parents : 64 + rows * evaluations + split,
                                                 circuits, bores, seed);
  std::vector<mold::Genome> warm(all.begin(), all.begin() + (mutations ? parents : 64));
  if (mutations) {
    const auto children = mutated_children(session.problem(), warm, rows * evaluations + split, seed + 1);
    all.insert(all.end(), children.begin(), children.end());
  }
  auto slice = [&, next = warm.size()](int count) mutable {
    std::vector<mold::Genome> out(all.begin() + long(next), all.begin() + long(next) + count);
    next += std::size_t(count);
    return out;
  };
  std::cout << "mold,threads,bores,samples,evaluations_per_second\n";
  for (int row = 0; row < rows; ++row) {
    const int t = row == 0 ? 1 : threads;
    const auto r = bench_evaluate(session.pipeline(), warm, slice(evaluations), t);
    std::cout << mold_path << ',' << t << ',' << r.bores << ',' << r.samples << ',' << r.evaluations_per_second << '\n';
  }
  std::cerr << "stage,microseconds_per_evaluation\n";
  for (const auto& [name, sec] : stage_split(session.pipeline(), warm, slice(split)))
    std::cerr << name << ',' << sec * 1e6 << '\n';
  return 0;
}

}  // namespace mtcs::bench
