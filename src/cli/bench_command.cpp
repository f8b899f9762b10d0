// mtcs bench: timings and errors of the cylinder kernel against the certified intervals, with
// FCL measured in the same run as the peer. Each pair is timed over `repeat` back-to-back
// queries (one clock read per batch); medians and 99th percentiles are over pairs.

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <iostream>
#include <map>
#include <memory>

#include "mtcs/io/atomic_file.h"

#include "bench_clearance.h"
#include "bench_evaluate.h"
#include "bench_hypervolume.h"
#include "bench_interfere.h"
#include "bench_sms.h"
#include "bench_optimize.h"
#include "mtcs/mold/layout_io.h"
#include "run_config.h"
#include "fcl_peer.h"
#include "mtcs/cli/commands.h"
#include "mtcs/io/pairs_csv.h"
#include "mtcs/geometry/cylinder_distance.h"
#include "mtcs/geometry/segment_distance.h"

namespace mtcs::cli {

using io::CylinderPair;
using io::read_pairs_csv;
namespace {

using geometry::DistanceRequest;
using geometry::DistanceResult;

struct Sample {
  double ns;
  double err;      // distance from the answer to the certified interval (0 without one)
  double rel_err;  // err / max(1, S)
  const CylinderPair* pair;
};

// Error of a result against the pair's certified interval. A bounded result claims only
// "distance >= U": it is wrong by how far the interval lies below U.
double error_of(const CylinderPair& p, double d, bool bounded, double upper) {
  if (!p.dist_lo || !p.dist_hi) return 0;
  if (bounded) return std::max(0.0, upper * (1 - 1e-12) - *p.dist_hi);
  return std::max({0.0, *p.dist_lo - d, d - *p.dist_hi});
}

template <class F>
Sample time_one(const CylinderPair& p, int repeat, F&& query) {
  volatile double sink = 0;
  const auto t0 = std::chrono::steady_clock::now();
  for (int k = 0; k < repeat; ++k) sink = sink + query();
  const auto t1 = std::chrono::steady_clock::now();
  (void)sink;
  return {std::chrono::duration<double, std::nano>(t1 - t0).count() / repeat, 0, 0, &p};
}

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0;
  const std::size_t k = std::min(v.size() - 1, std::size_t(q * double(v.size() - 1) + 0.5));
  std::nth_element(v.begin(), v.begin() + long(k), v.end());
  return v[k];
}

std::string subtype_of(const std::string& id) {
  const auto dash = id.rfind('-');
  return dash == std::string::npos ? id : id.substr(0, dash);
}

using Variant = std::function<Sample(const CylinderPair&)>;

std::map<std::string, Variant> make_variants(int repeat, double tolerance) {
  std::map<std::string, Variant> v;
  auto kernel = [repeat](DistanceRequest rq) {
    return [repeat, rq](const CylinderPair& p) {
      DistanceResult r;
      Sample s = time_one(p, repeat, [&] { r = geometry::distance(p.a, p.b, rq); return r.distance; });
      s.err = error_of(p, r.distance, r.bounded, rq.upper_bound);
      return s;
    };
  };
  DistanceRequest full;
  full.tolerance = tolerance;
  v["full"] = kernel(full);
  DistanceRequest u5 = full;
  u5.upper_bound = 5;
  v["bounded-U5"] = kernel(u5);
  DistanceRequest np = full;
  np.pretests = false;
  v["no-pretests"] = kernel(np);
  DistanceRequest ns = full;
  ns.sorted_bounds = false;
  v["no-sorted-bounds"] = kernel(ns);
  v["naive"] = [repeat, tolerance](const CylinderPair& p) {
    DistanceResult r;
    Sample s = time_one(p, repeat, [&] { r = geometry::distance_naive(p.a, p.b, tolerance); return r.distance; });
    s.err = error_of(p, r.distance, false, 0);
    return s;
  };
  v["fcl"] = [repeat](const CylinderPair& p) {
    const FclPair f(p.a, p.b);
    double d = 0;
    Sample s = time_one(p, repeat, [&] { d = f.distance(); return d; });
    s.err = error_of(p, d, false, 0);
    return s;
  };
  v["segment-floor"] = [repeat](const CylinderPair& p) {
    const geometry::Segment sa{p.a.p0, p.a.p1}, sb{p.b.p0, p.b.p1};
    double d = 0;
    Sample s = time_one(p, repeat, [&] { d = geometry::closest_points(sa, sb).distance; return d; });
    // The capsule distance, for reference only: it is not a cylinder distance.
    s.err = error_of(p, std::max(0.0, d - p.a.radius - p.b.radius), false, 0);
    return s;
  };
  return v;
}

std::vector<Sample> run_variant(const Variant& variant, const std::vector<CylinderPair>& pairs) {
  std::vector<Sample> out;
  out.reserve(pairs.size());
  for (const auto& p : pairs) {
    Sample s = variant(p);
    s.rel_err = s.err / std::max(1.0, geometry::pair_scale(p.a, p.b));
    out.push_back(s);
  }
  return out;
}

std::map<std::string, std::vector<const Sample*>> group(const std::vector<Sample>& samples,
                                                        bool by_subtype) {
  std::map<std::string, std::vector<const Sample*>> g;
  for (const auto& s : samples) {
    g[by_subtype ? subtype_of(s.pair->id) : s.pair->category].push_back(&s);
    g["all"].push_back(&s);
  }
  return g;
}

std::vector<double> field(const std::vector<const Sample*>& v, double Sample::*m) {
  std::vector<double> out;
  out.reserve(v.size());
  for (const Sample* s : v) out.push_back(s->*m);
  return out;
}

}  // namespace

Command add_bench_command(CLI::App& app) {
  struct Options {
    std::string pairs;
    std::vector<std::string> variants{"full", "bounded-U5", "no-pretests", "no-sorted-bounds",
                                      "naive", "fcl", "segment-floor"};
    int repeat = 8;
    double tolerance = 1e-12;
    std::vector<double> sweep{1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10,
                              1e-11, 1e-12, 1e-13, 1e-14, 1e-15};
  };
  auto opt = std::make_shared<Options>();
  CLI::App* bench = app.add_subcommand("bench", "Benchmarks of the kernels, against peers measured in the same run.");
  bench->require_subcommand(1);

  CLI::App* dist = bench->add_subcommand(
      "distance",
      "Cylinder distance: median and p99 ns per query and max error against the certified\n"
      "intervals, per category, for each variant. CSV on stdout:\n"
      "  variant,category,n,median_ns,p99_ns,max_abs_err\n"
      "Variants: full, bounded-U5, no-pretests, no-sorted-bounds, naive, fcl, segment-floor.\n"
      "Example: mtcs bench distance --pairs tests/data/cylinder_pairs_public.csv");
  CLI::App* sweep = bench->add_subcommand(
      "tolerance",
      "Error against run time: the full kernel at each tolerance of its numerical parts. CSV:\n"
      "  tolerance,category,n,median_ns,max_abs_err,median_abs_err,max_rel_err");
  CLI::App* stiff = bench->add_subcommand(
      "stiff",
      "Worst errors of the full kernel by pair sub-type (id without its number). CSV:\n"
      "  subtype,n,median_ns,max_abs_err,max_rel_err,worst_id");
  CLI::App* evaluate = bench->add_subcommand(
      "evaluate",
      "Evaluations per second of random layouts (circuits x bores axis-parallel legs), on one\n"
      "thread and on --threads threads. CSV on stdout:\n"
      "  mold,threads,bores,samples,evaluations_per_second\n"
      "and the mean time per evaluation of each stage on stderr.\n"
      "Example: mtcs bench evaluate molds/plate.yaml --threads 2");
  struct EvalOptions {
    std::string mold;
    int threads = 2, evaluations = 20000, circuits = 3, bores = 8;
    std::uint64_t seed = 1;
  };
  auto eo = std::make_shared<EvalOptions>();
  evaluate->add_option("mold", eo->mold, "mold spec")->required();
  evaluate->add_option("--threads", eo->threads, "threads for the parallel row")->capture_default_str()->check(CLI::Range(1, 256));
  evaluate->add_option("--evaluations", eo->evaluations, "layouts per row")->capture_default_str()->check(CLI::Range(100, 100000000));
  evaluate->add_option("--circuits", eo->circuits, "circuits per layout")->capture_default_str()->check(CLI::Range(1, 100));
  evaluate->add_option("--bores", eo->bores, "bores per circuit")->capture_default_str()->check(CLI::Range(3, 1000));
  evaluate->add_option("--seed", eo->seed, "seed of the random layouts")->capture_default_str();

  CLI::App* optimize = bench->add_subcommand(
      "optimize",
      "One optimiser on one mold over seeds 1..K at an equal budget. CSV on stdout:\n"
      "  mold,algorithm,seed,evaluations,best_objective,feasible,seconds\n"
      "and with --trace FILE the convergence (algorithm,seed,evaluations,best_feasible).\n"
      "Algorithms: es, random (random search), nlopt (GN_ISRES on the coordinates of --topology).\n"
      "Example: mtcs bench optimize molds/plate.yaml --algorithm es --seeds 11 --evaluations 20000");
  struct OptOptions {
    std::string mold, algorithm = "es", config, topology, trace;
    int seeds = 11;
    long evaluations = 20000;
  };
  auto oo = std::make_shared<OptOptions>();
  optimize->add_option("mold", oo->mold, "mold spec")->required();
  optimize->add_option("--algorithm", oo->algorithm, "es, random or nlopt")->capture_default_str()
      ->check(CLI::IsMember({"es", "random", "nlopt"}));
  optimize->add_option("--config", oo->config, "run config (ES settings)");
  optimize->add_option("--topology", oo->topology,
                       "layout whose topology (and start) nlopt keeps (default: the seed's first random sample)");
  optimize->add_option("--seeds", oo->seeds, "seeds 1..K")->capture_default_str()->check(CLI::Range(1, 1000));
  optimize->add_option("--evaluations", oo->evaluations, "budget per run")->capture_default_str();
  optimize->add_option("--trace", oo->trace, "convergence CSV to write");

  CLI::App* hv = bench->add_subcommand(
      "hypervolume",
      "Hypervolume and all contributions, ours against pagmo 2.18 in the same run, on every front\n"
      "of a folder (one point per line, '# ref ...'; expected.csv with exact values if present).\n"
      "Example: mtcs bench hypervolume --fronts tests/data/hv_fronts");
  struct HvOptions {
    std::string fronts;
    int repeat = 3;
    std::size_t max_contribution_n = 1000;
  };
  auto ho = std::make_shared<HvOptions>();
  hv->add_option("--fronts", ho->fronts, "folder of fronts")->required()->check(CLI::ExistingDirectory);
  hv->add_option("--repeat", ho->repeat, "timed repetitions (median)")->capture_default_str();
  hv->add_option("--max-contribution-n", ho->max_contribution_n, "largest front whose contributions are timed")
      ->capture_default_str();

  CLI::App* sms = bench->add_subcommand(
      "sms-emoa",
      "Our SMS-EMOA against pagmo's NSGA-II and MOEA/D (mu = 100) on a ZDT or DTLZ problem, same\n"
      "budget and seeds; hypervolume of each final non-dominated set against (1.1, ...). CSV:\n"
      "  problem,algorithm,seed,evaluations,hypervolume,seconds\n"
      "Example: mtcs bench sms-emoa --problem zdt1 --seeds 11 --evaluations 20000");
  struct SmsOptions {
    std::string problem = "zdt1";
    std::vector<std::string> algorithms{"sms-emoa", "nsga2", "moead"};
    int seeds = 11;
    long evaluations = 20000;
  };
  auto so = std::make_shared<SmsOptions>();
  sms->add_option("--problem", so->problem, "zdt1-4, zdt6, dtlz1-7")->capture_default_str();
  sms->add_option("--algorithms", so->algorithms, "sms-emoa, nsga2, moead")->delimiter(',');
  sms->add_option("--seeds", so->seeds, "seeds 1..K")->capture_default_str();
  sms->add_option("--evaluations", so->evaluations, "budget per run")->capture_default_str();

  struct ClearanceOptions {
    std::vector<std::string> meshes, cases;
    int repeat = 3, builds = 3;
    double bound_fraction = 0.02;
  };
  auto co = std::make_shared<ClearanceOptions>();
  CLI::App* clearance = bench->add_subcommand(
      "clearance",
      "Cylinder vs closed mesh against FCL 0.7 in the same run: BVH build time, median and p90\n"
      "microseconds per query, max error over S and wrong verdicts against the certified\n"
      "intervals, per category; ours exact, ours with the upper bound (bound-fraction x the\n"
      "mesh's largest extent), ours on a median-split BVH, FCL. CSV on stdout:\n"
      "  mesh,triangles,method,upper_bound,build_ms,category,n,median_us,p90_us,max_rel_err,wrong_verdicts");
  clearance->footer(
      "Example:\n"
      "  mtcs bench clearance --mesh tests/data/meshes/homer.off --cases tests/data/mesh_clearance/homer.csv\n"
      "  (repeat --mesh/--cases for several meshes, in the same order)");
  clearance->add_option("--mesh", co->meshes, "closed mesh (repeatable)")->required()->check(CLI::ExistingFile);
  clearance->add_option("--cases", co->cases, "certified cases of that mesh (repeatable)")->required()->check(CLI::ExistingFile);
  clearance->add_option("--repeat", co->repeat, "queries per timed batch")->capture_default_str()->check(CLI::Range(1, 100000));
  clearance->add_option("--builds", co->builds, "BVH builds timed (median)")->capture_default_str()->check(CLI::Range(1, 100));
  clearance->add_option("--bound-fraction", co->bound_fraction, "upper bound of ours-bounded, x largest extent")
      ->capture_default_str()->check(CLI::PositiveNumber);
  CLI::App* interfere = bench->add_subcommand(
      "interfere",
      "All intersecting triangle pairs of two placed meshes: ours (median split, and split by solid\n"
      "and face first) against FCL 0.7's all-contacts collide (BVHModel<OBBRSS>) and CGAL 5.5's\n"
      "PMP::do_intersect, same run, same doubles; pair counts against the exact ones, distances at\n"
      "gap placements against the certified intervals. Median of --repeat runs. CSV on stdout.\n"
      "Example: mtcs bench interfere --cases tests/data/mesh_interference.csv --meshes tests/data/meshes");
  struct InterfereOptions {
    std::string cases, meshes;
    int repeat = 5;
  };
  auto io_opt = std::make_shared<InterfereOptions>();
  interfere->add_option("--cases", io_opt->cases, "mesh_interference.csv")->required()->check(CLI::ExistingFile);
  interfere->add_option("--meshes", io_opt->meshes, "folder of the meshes (NAME.off)")->required()->check(CLI::ExistingDirectory);
  interfere->add_option("--repeat", io_opt->repeat, "timed repetitions (median)")->capture_default_str();

  for (CLI::App* s : {dist, sweep, stiff}) {
    s->add_option("--pairs", opt->pairs, "CSV of cylinder pairs with dist_lo, dist_hi")->required()->check(CLI::ExistingFile);
    s->add_option("--repeat", opt->repeat, "queries per timed batch")->capture_default_str()->check(CLI::Range(1, 1000000));
  }
  dist->add_option("--variants", opt->variants, "variants to run")->delimiter(',');
  dist->add_option("--tolerance", opt->tolerance, "kernel tolerance")->capture_default_str();
  stiff->add_option("--tolerance", opt->tolerance, "kernel tolerance")->capture_default_str();
  sweep->add_option("--tolerances", opt->sweep, "tolerances to sweep")->delimiter(',');

  return {bench, [opt, dist, sweep, stiff, evaluate, eo, optimize, oo, hv, ho, sms, so, clearance, co, interfere, io_opt] {
            if (clearance->parsed()) return bench_clearance(co->meshes, co->cases, co->repeat, co->builds, co->bound_fraction);
            if (interfere->parsed()) return bench_interfere(io_opt->cases, io_opt->meshes, io_opt->repeat);
            if (hv->parsed()) return bench_hypervolume(ho->fronts, ho->repeat, ho->max_contribution_n);
            if (sms->parsed()) return bench_sms(so->problem, so->algorithms, so->seeds, so->evaluations);
            if (optimize->parsed()) {
              const mold::Scene scene(mold::load_mold_spec(oo->mold));
              const eval::Pipeline pipeline(scene);
              const RunConfig config = oo->config.empty() ? RunConfig{} : load_run_config(oo->config, pipeline.objective_names());
              const MoldProblem problem(pipeline, config.weights, config.mutation);
              // NLopt's fixed topology: a layout file, or by default the seed's first random
              // sample (the same kind of start the ES gets).
              auto topology_for = [&](std::uint64_t seed) {
                if (!oo->topology.empty()) return mold::load_layout(oo->topology, scene.spec());
                opt::Rng rng = opt::Rng::for_individual(seed, 0, 0);
                return problem.genome(problem.sample(rng));
              };
              std::unique_ptr<io::AtomicFile> trace;
              if (!oo->trace.empty()) {
                trace = std::make_unique<io::AtomicFile>(oo->trace);
                trace->stream() << "algorithm,seed,evaluations,best_feasible\n";
              }
              std::cout << "mold,algorithm,seed,evaluations,best_objective,feasible,seconds\n";
              for (int seed = 1; seed <= oo->seeds; ++seed) {
                OptimizeTrace t;
                if (oo->algorithm == "nlopt") {
                  t = bench_nlopt(problem, scene, topology_for(std::uint64_t(seed)), oo->evaluations, std::uint64_t(seed));
                } else {
                  opt::EsConfig es = config.es;
                  es.seed = std::uint64_t(seed);
                  es.evaluations = oo->evaluations;
                  es.random_search = oo->algorithm == "random";
                  es.min_step = 0.1 * *std::min_element(scene.spec().drilling.diameters.begin(), scene.spec().drilling.diameters.end());
                  t = bench_es(problem, es);
                }
                std::cout << oo->mold << ',' << oo->algorithm << ',' << seed << ',' << oo->evaluations << ','
                          << t.best.value << ',' << (t.best.feasible ? 1 : 0) << ',' << t.seconds << std::endl;
                if (trace)
                  for (const auto& p : t.points)
                    trace->stream() << oo->algorithm << ',' << seed << ',' << p.evaluations << ',' << p.best_feasible << '\n';
              }
              if (trace) trace->commit();
              return 0;
            }
            if (evaluate->parsed()) {
              const mold::Scene scene(mold::load_mold_spec(eo->mold));
              const auto genomes = random_genomes(scene, eo->evaluations, eo->circuits, eo->bores, eo->seed);
              std::cout << "mold,threads,bores,samples,evaluations_per_second\n";
              std::vector<int> rows{1};
              if (eo->threads > 1) rows.push_back(eo->threads);
              for (const int t : rows) {
                const auto r = bench_evaluate(scene, genomes, t);
                std::cout << eo->mold << ',' << t << ',' << r.bores << ',' << r.samples << ',' << r.evaluations_per_second << '\n';
                if (t == 1) {
                  std::cerr << "stage,microseconds_per_evaluation\n";
                  for (const auto& [name, sec] : r.stage_seconds) std::cerr << name << ',' << sec * 1e6 << '\n';
                }
              }
              return 0;
            }
            const auto pairs = read_pairs_csv(opt->pairs);
            std::cout.precision(6);
            if (dist->parsed()) {
              auto variants = make_variants(opt->repeat, opt->tolerance);
              std::cout << "variant,category,n,median_ns,p99_ns,max_abs_err\n";
              for (const auto& name : opt->variants) {
                if (!variants.count(name)) throw std::runtime_error("unknown variant '" + name + "'");
                const auto samples = run_variant(variants[name], pairs);
                for (const auto& [cat, v] : group(samples, false)) {
                  const auto ns = field(v, &Sample::ns), err = field(v, &Sample::err);
                  std::cout << name << ',' << cat << ',' << v.size() << ',' << quantile(ns, 0.5) << ','
                            << quantile(ns, 0.99) << ',' << *std::max_element(err.begin(), err.end()) << '\n';
                }
              }
            } else if (sweep->parsed()) {
              std::cout << "tolerance,category,n,median_ns,max_abs_err,median_abs_err,max_rel_err\n";
              for (const double tol : opt->sweep) {
                const auto samples = run_variant(make_variants(opt->repeat, tol)["full"], pairs);
                for (const auto& [cat, v] : group(samples, false)) {
                  const auto ns = field(v, &Sample::ns), err = field(v, &Sample::err),
                             rel = field(v, &Sample::rel_err);
                  std::cout << tol << ',' << cat << ',' << v.size() << ',' << quantile(ns, 0.5) << ','
                            << *std::max_element(err.begin(), err.end()) << ',' << quantile(err, 0.5) << ','
                            << *std::max_element(rel.begin(), rel.end()) << '\n';
                }
              }
            } else if (stiff->parsed()) {
              const auto samples = run_variant(make_variants(opt->repeat, opt->tolerance)["full"], pairs);
              std::cout << "subtype,n,median_ns,max_abs_err,max_rel_err,worst_id\n";
              for (const auto& [sub, v] : group(samples, true)) {
                const Sample* worst = *std::max_element(
                    v.begin(), v.end(), [](const Sample* x, const Sample* y) { return x->rel_err < y->rel_err; });
                const auto ns = field(v, &Sample::ns), err = field(v, &Sample::err);
                std::cout << sub << ',' << v.size() << ',' << quantile(ns, 0.5) << ','
                          << *std::max_element(err.begin(), err.end()) << ',' << worst->rel_err << ','
                          << worst->pair->id << '\n';
              }
            }
            return 0;
          }};
}

}  // namespace mtcs::cli
