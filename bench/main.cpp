// mtcs-bench: benchmarks of the kernels and the optimisers, against peers (FCL, pagmo, CGAL,
// NLopt) measured in the same run. `mtcs bench ARGS` runs `mtcs-bench ARGS`; the production
// binary links none of the peers.

#include <CLI/CLI.hpp>
#include <spdlog/sinks/stdout_sinks.h>
#include <spdlog/spdlog.h>
#include <iostream>
#include <memory>

#include "bench_access_map.h"
#include "bench_clearance.h"
#include "bench_distance.h"
#include "bench_evaluate.h"
#include "bench_hypervolume.h"
#include "bench_interfere.h"
#include "bench_optimize.h"
#include "bench_part.h"
#include "bench_sms.h"
#include "bench_thermal.h"
#include "mtcs/io/input_error.h"

namespace mtcs::bench {
namespace {

int run(int argc, char** argv) {
  // Log lines (a model's build) on stderr: stdout is the benchmark's CSV.
  spdlog::set_default_logger(spdlog::stderr_logger_st("mtcs-bench"));
  CLI::App app{"mtcs bench - benchmarks of the kernels, against peers measured in the same run.", "mtcs bench"};
  app.require_subcommand(1);

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

  CLI::App* dist = app.add_subcommand(
      "distance",
      "Cylinder distance: median and p99 ns per query and max error against the certified\n"
      "intervals, per category, for each variant. CSV on stdout:\n"
      "  variant,category,n,median_ns,p99_ns,max_abs_err\n"
      "Variants: full, bounded-U5, no-pretests, no-sorted-bounds, naive, fcl, segment-floor.\n"
      "Example: mtcs bench distance --pairs tests/data/cylinder_pairs_public.csv");
  CLI::App* sweep = app.add_subcommand(
      "tolerance",
      "Error against run time: the full kernel at each tolerance of its numerical parts. CSV:\n"
      "  tolerance,category,n,median_ns,max_abs_err,median_abs_err,max_rel_err");
  CLI::App* stiff = app.add_subcommand(
      "stiff",
      "Worst errors of the full kernel by pair sub-type (id without its number). CSV:\n"
      "  subtype,n,median_ns,max_abs_err,max_rel_err,worst_id");
  CLI::App* evaluate = app.add_subcommand(
      "evaluate",
      "Evaluations per second of random layouts (circuits x bores axis-parallel legs), on one\n"
      "thread and on --threads threads. CSV on stdout:\n"
      "  mold,threads,bores,samples,evaluations_per_second\n"
      "and the mean time per evaluation of each stage on stderr. With --mutations the layouts are\n"
      "children of real mutations (the mold problem's operators, the run config's rates) of a\n"
      "population of random parents evaluated first, as in a run: the stages' caches see what\n"
      "an ES run gives them.\n"
      "Example: mtcs bench evaluate molds/plate.yaml --threads 2 --mutations");
  struct EvalOptions {
    std::string mold;
    int threads = 2, evaluations = 20000, circuits = 3, bores = 8;
    std::uint64_t seed = 1;
    bool mutations = false;
    std::string config;
  };
  auto eo = std::make_shared<EvalOptions>();
  evaluate->add_option("mold", eo->mold, "mold spec")->required();
  evaluate->add_option("--threads", eo->threads, "threads for the parallel row")->capture_default_str()->check(CLI::Range(1, 256));
  evaluate->add_option("--evaluations", eo->evaluations, "layouts per row")->capture_default_str()->check(CLI::Range(100, 100000000));
  evaluate->add_option("--circuits", eo->circuits, "circuits per layout")->capture_default_str()->check(CLI::Range(1, 100));
  evaluate->add_option("--bores", eo->bores, "bores per circuit")->capture_default_str()->check(CLI::Range(3, 1000));
  evaluate->add_option("--seed", eo->seed, "seed of the random layouts")->capture_default_str();
  evaluate->add_flag("--mutations", eo->mutations, "time children of mutations of random parents, not random layouts");
  evaluate->add_option("--config", eo->config, "RUN.yaml whose mutation rates make the children (default: the defaults)");

  CLI::App* part = app.add_subcommand(
      "part",
      "What a designer waits for on a mold with a part: mtcs evaluate and mtcs thermal of its layout\n"
      "as a user runs them (a process each; cold: an empty cache folder, warm: the folder the cold\n"
      "run filled), wall time and peak memory, with every --peer binary's commands run in turn in the\n"
      "same run (old and new builds on one machine state); then in this process on one thread: the\n"
      "first score of the layout (session and model, cache warm), children of the optimiser's\n"
      "mutations of it per second, random layouts (3 circuits of 5 legs) per second. CSV on stdout:\n"
      "  mold,program,measure,value,unit\n"
      "Example: mtcs bench part molds/cup.yaml --peer /tmp/mtcs-old --repeat 3");
  auto po = std::make_shared<PartBenchOptions>();
  part->add_option("mold", po->mold, "mold spec")->required();
  part->add_option("--layout", po->layout, "layout (default: MOLD.layout.yaml beside the mold)");
  part->add_option("--peer", po->peers, "another mtcs binary whose commands run in the same run");
  part->add_option("--repeat", po->repeat, "runs of each command (the median)")->capture_default_str()->check(CLI::Range(1, 100));
  part->add_option("--children", po->children, "children timed")->capture_default_str()->check(CLI::Range(1, 1000000));
  part->add_option("--randoms", po->randoms, "random layouts timed")->capture_default_str()->check(CLI::Range(1, 1000000));
  part->add_option("--seed", po->seed, "seed of the children and random layouts")->capture_default_str();
  part->add_flag("--optimize", po->optimize, "also the default mtcs optimize --seed 1 (wall time, peak memory)");

  CLI::App* optimize = app.add_subcommand(
      "optimize",
      "Optimisers on one mold over seeds 1..K at an equal budget. CSV on stdout:\n"
      "  mold,algorithm,seed,evaluations,best_objective,feasible,seconds,hypervolume\n"
      "and with --trace FILE the anytime course (algorithm,seed,evaluations,best_feasible,seconds,hypervolume).\n"
      "Algorithms: es, sms-emoa, random (mtcs's, on the mold problem); isres, crs2 (NLopt), cmaes, nsga2,\n"
      "moead (pagmo) on the coordinates of a fixed topology (--topology, default each seed's first sample);\n"
      "nlopt: isres under its old name. Hypervolume: feasible non-dominated layouts evaluated, scaled.\n"
      "Example: mtcs bench optimize molds/plate.yaml --algorithm es nsga2 --seeds 11 --evaluations 20000");
  auto oo = std::make_shared<OptimizeRuns>();
  optimize->add_option("mold", oo->mold, "mold spec")->required();
  optimize->add_option("--algorithm", oo->algorithms, "one or more of es, sms-emoa, random, isres, crs2, cmaes, nsga2, moead")
      ->capture_default_str()
      ->check(CLI::IsMember({"es", "sms-emoa", "random", "isres", "crs2", "cmaes", "nsga2", "moead", "nlopt"}));
  optimize->add_option("--config", oo->config, "run config (ES settings)");
  optimize->add_option("--topology", oo->topology,
                       "layout whose topology (and start) the fixed-topology peers keep (default: the seed's first random sample)");
  optimize->add_option("--seeds", oo->seeds, "seeds 1..K")->capture_default_str()->check(CLI::Range(1, 1000));
  optimize->add_option("--evaluations", oo->evaluations, "budget per run")->capture_default_str();
  optimize->add_option("--trace", oo->trace, "anytime CSV to write");
  optimize->add_option("--layouts", oo->layouts, "folder for each run's best layout, ALGORITHM-seedS.layout.yaml (mtcs evaluate --layout)");
  optimize->add_option("--trace-every", oo->trace_every, "evaluations between anytime points (default: budget / 100)");

  CLI::App* hv = app.add_subcommand(
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

  CLI::App* sms = app.add_subcommand(
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
  CLI::App* clearance = app.add_subcommand(
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
      ->capture_default_str()->delimiter(',')->check(CLI::PositiveNumber);
  CLI::App* interfere = app.add_subcommand(
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

  auto to = std::make_shared<ThermalBenchOptions>();
  CLI::App* thermal = app.add_subcommand(
      "thermal",
      "Error against run time of the thermal tiers (t0 wall distance, t1, t2, t2d line sinks with M\n"
      "elements per bore, fd finite volumes at a cell size) on random layouts, against the finite\n"
      "volumes at --reference-cell: ms per evaluation (full; incremental = one bore moved, warm\n"
      "cache), RMS and max error at the samples (K), Kendall tau of the samples' std, mean and max,\n"
      "tau among the better half, top-10 overlap, and on a mold the tau of cycle_time (the slowest\n"
      "place's, at the nominal cycle's films), with cavity.parting of temperature_std_side, and\n"
      "with --difference of temperature_difference.\n"
      "CSV on stdout, or --json:\n"
      "  {default_tier, tiers: [{tier, ms_full, ms_incremental, rms_k, tau_std, ...}]}\n"
      "--case block: the reference block of shared/cases/thermal with 2-5 through-bores along x;\n"
      "--case MOLD.yaml: a mold's cavity with random layouts (3 circuits of 4 legs).\n"
      "Example: mtcs bench thermal --case block --layouts 60 --reference-cell 1");
  thermal->add_option("--case", to->scene, "block or a mold spec")->capture_default_str();
  thermal->add_option("--layouts", to->layouts, "random layouts")->capture_default_str()->check(CLI::Range(3, 100000));
  thermal->add_option("--reference-cell", to->reference_cell, "mm, the finite-volume reference's cell")
      ->capture_default_str()->check(CLI::Range(0.25, 50.0));
  thermal->add_option("--seed", to->seed, "seed of the layouts")->capture_default_str();
  thermal->add_option("--repeat", to->repeat, "timed solves per layout (median)")->capture_default_str()->check(CLI::Range(1, 1000));
  thermal->add_option("--void-panels", to->void_panels,
                      "mm: with a mesh cavity, also t2d M=4 knowing the part's void, panels this wide (one tier each)")
      ->capture_default_str()->delimiter(',')->check(CLI::PositiveNumber);
  thermal->add_option("--circuits", to->circuits, "circuits of 4 legs per random layout of a mold")
      ->capture_default_str()->check(CLI::Range(1, 16));
  thermal->add_flag("--through-part", to->through_part,
                    "a mold: keep the random layouts whose bores cross the part (by default only those clear of it)");
  thermal->add_option("--tiers", to->tiers, "only the tiers whose labels start so, comma-separated (e.g. \"t0,t2d M=4\")")
      ->delimiter(',');
  thermal->add_option("--sample-images", to->sample_images,
                      "also every line-sink tier with this many image levels summed exactly at the samples "
                      "(label ends S=N; the model chooses otherwise)")
      ->delimiter(',')->check(CLI::Range(1, 4));
  thermal->add_flag("--difference", to->difference,
                    "a mold: also the points across the part's wall, for the tau of temperature_difference "
                    "(they are solved for too: the times grow as the stage's do with that objective)");
  thermal->add_flag("--json", to->json, "one JSON object instead of CSV");

  auto ao = std::make_shared<AccessMapBenchOptions>();
  CLI::App* access = app.add_subcommand(
      "access-map",
      "Accessibility maps: AICA, ICA and the exact CheckBox on every case file (*.txt) of a folder\n"
      "in one run; per method the median and p90 ms per map (best of --repeat runs; thread CPU time\n"
      "on one thread, wall time on more), the ICA efficiency (share of node tests needing no exact\n"
      "CheckBox) and the cells differing from CheckBox. CSV on stdout:\n"
      "  method,cases,median_ms,p90_ms,node_tests,checkbox_calls,ica_efficiency,differing_cells,\n"
      "  median_speedup_vs_checkbox\n"
      "or --json: {median_speedup_vs_checkbox (AICA), ica_efficiency (AICA), differing_cells (AICA\n"
      "and ICA), methods: [...]}. Meshes: the case's `mesh` line under --mesh-root, else its file\n"
      "name under --mesh-root; without --mesh-root as `mtcs access-map --case` finds them.\n"
      "Example: mtcs bench access-map --cases tests/data/access_maps --mesh-root tests/data/meshes");
  access->add_option("--cases", ao->cases, "folder of case files")->required()->check(CLI::ExistingDirectory);
  access->add_option("--mesh-root", ao->mesh_root, "folder the meshes are resolved against")->check(CLI::ExistingDirectory);
  access->add_option("--threads", ao->threads, "threads per map")->capture_default_str()->check(CLI::Range(1, 256));
  access->add_option("--repeat", ao->repeat, "timed runs per map (best)")->capture_default_str()->check(CLI::Range(1, 1000));
  access->add_option_function<std::vector<int>>(
            "--am", [ao](const std::vector<int>& v) { ao->am_rows = v.at(0), ao->am_cols = v.at(1); },
            "ROWS,COLS: sphere grid instead of the cases' own")
      ->delimiter(',')->expected(2)->check(CLI::Range(1, 4096));
  access->add_flag("--json", ao->json, "one JSON object instead of CSV");

  for (CLI::App* s : {dist, sweep, stiff}) {
    s->add_option("--pairs", opt->pairs, "CSV of cylinder pairs with dist_lo, dist_hi")->required()->check(CLI::ExistingFile);
    s->add_option("--repeat", opt->repeat, "queries per timed batch")->capture_default_str()->check(CLI::Range(1, 1000000));
  }
  dist->add_option("--variants", opt->variants, "variants to run")->delimiter(',');
  dist->add_option("--tolerance", opt->tolerance, "kernel tolerance")->capture_default_str();
  stiff->add_option("--tolerance", opt->tolerance, "kernel tolerance")->capture_default_str();
  sweep->add_option("--tolerances", opt->sweep, "tolerances to sweep")->delimiter(',');

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  if (access->parsed()) return bench_access_map(*ao);
  if (thermal->parsed()) return bench_thermal(*to);
  if (clearance->parsed()) return bench_clearance(co->meshes, co->cases, co->repeat, co->builds, co->bound_fraction);
  if (interfere->parsed()) return bench_interfere(io_opt->cases, io_opt->meshes, io_opt->repeat);
  if (hv->parsed()) return bench_hypervolume(ho->fronts, ho->repeat, ho->max_contribution_n);
  if (sms->parsed()) return bench_sms(so->problem, so->algorithms, so->seeds, so->evaluations);
  if (optimize->parsed()) return bench_optimize(*oo);
  if (part->parsed()) return bench_part(*po);
  if (evaluate->parsed())
    return bench_evaluate_rows(eo->mold, eo->threads, eo->evaluations, eo->circuits, eo->bores, eo->seed,
                               eo->mutations, eo->config);
  if (dist->parsed()) return bench_distance(opt->pairs, opt->variants, opt->repeat, opt->tolerance);
  if (sweep->parsed()) return bench_tolerance(opt->pairs, opt->sweep, opt->repeat);
  return bench_stiff(opt->pairs, opt->repeat, opt->tolerance);
}

}  // namespace
}  // namespace mtcs::bench

int main(int argc, char** argv) {
  try {
    return mtcs::bench::run(argc, argv);
  } catch (const mtcs::io::InputError& e) {
    std::cerr << "mtcs: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "mtcs: error: " << e.what() << "\n";
    return 1;
  }
}
