// The plate's temperature objectives at coarser thermal samples (thermal.sample_spacing) against
// the cavity's own samples, same tier: mean, std and max per layout and spacing, and the time of
// a cold solve. Layouts: random genomes (bench evaluate's generator) and ES results from files.
// With FD_CELL=c (mm) also T3 at the cavity's samples, as the truth for the ranking, for the
// layout sets whose names begin with FD_SETS (default random3x4; "es:" the files, "" all).
//
//   (build: see plate_samples.md)
//   ./plate_samples molds/plate.yaml "8 11 16.5" experiments/thermal/es_plate_layouts/*.layout.yaml > out.csv

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "bench/bench_evaluate.h"
#include "mtcs/eval/temperature_objectives.h"
#include "mtcs/eval/thermal_model.h"
#include "mtcs/eval/thermal_tiers.h"
#include "mtcs/mold/decoder.h"
#include "mtcs/mold/layout_io.h"
#include "mtcs/mold/scene.h"

using namespace mtcs;

struct Named {
  std::string set, name;
  mold::Genome genome;
};

int main(int argc, char** argv) {
  if (argc < 3) return std::fprintf(stderr, "usage: plate_samples MOLD \"SPACINGS\" [LAYOUT.yaml...]\n"), 2;
  const mold::MoldSpec base = mold::load_mold_spec(argv[1]);
  std::vector<double> spacings{0};  // 0: the cavity's own samples (the key unset)
  std::istringstream in(argv[2]);
  for (double s; in >> s;) spacings.push_back(s);

  const mold::Scene base_scene(base);
  std::vector<Named> layouts;
  auto add = [&](const std::string& set, const std::vector<mold::Genome>& g) {
    for (std::size_t i = 0; i < g.size(); ++i) layouts.push_back({set, set + "-" + std::to_string(i), g[i]});
  };
  add("random3x4", bench::random_genomes(base_scene, 60, 3, 4, 1));
  add("random2x3", bench::random_genomes(base_scene, 30, 2, 3, 2));
  add("random1x3", bench::random_genomes(base_scene, 30, 1, 3, 3));
  for (int a = 3; a < argc; ++a) {
    const std::filesystem::path p(argv[a]);
    layouts.push_back({"es:" + p.parent_path().filename().string(), p.filename().string(), mold::load_layout(p, base)});
  }

  std::printf("set,layout,tier,spacing,samples,mean,std,max,ms\n");
  for (const double spacing : spacings) {
    mold::MoldSpec spec = base;
    if (spacing > 0) spec.thermal.sample_spacing = spacing;
    const mold::Scene scene(spec);
    const thermal::Setting setting = eval::thermal_setting(scene);
    const thermal::Samples samples = eval::thermal_samples(scene);
    const eval::TemperatureSolver solve = eval::temperature_solver(spec.thermal.tier)(setting, samples, spec.thermal);
    for (const Named& l : layouts) {
      const auto channels = eval::thermal_channels(mold::decode(scene, l.genome), spec);
      const auto t0 = std::chrono::steady_clock::now();
      const eval::TemperatureObjectives o = eval::temperature_objectives(solve(channels).temperature, samples, spec);
      const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      std::printf("%s,%s,%s,%g,%zu,%.9g,%.9g,%.9g,%.3f\n", l.set.c_str(), l.name.c_str(),
                  mold::to_string(spec.thermal.tier).c_str(), spacing > 0 ? spacing : base.cavity->sample_spacing,
                  samples.size(), o.mean, o.std, o.max, ms);
      std::fflush(stdout);
    }
  }
  if (const char* cell = std::getenv("FD_CELL")) {
    mold::MoldSpec spec = base;
    spec.thermal.cell_size = std::atof(cell);
    const mold::Scene scene(spec);
    const thermal::Setting setting = eval::thermal_setting(scene);
    const thermal::Samples samples = eval::thermal_samples(scene);
    const eval::TemperatureSolver solve = eval::temperature_solver(mold::ThermalTier::Fd)(setting, samples, spec.thermal);
    const std::string fd_sets = std::getenv("FD_SETS") ? std::getenv("FD_SETS") : "random3x4";
    for (const Named& l : layouts) {
      if (l.set.rfind(fd_sets, 0) != 0) continue;
      const auto t0 = std::chrono::steady_clock::now();
      const eval::TemperatureObjectives o =
          eval::temperature_objectives(solve(eval::thermal_channels(mold::decode(scene, l.genome), spec)).temperature, samples, spec);
      const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      std::printf("%s,%s,fd%s,%g,%zu,%.9g,%.9g,%.9g,%.3f\n", l.set.c_str(), l.name.c_str(), cell,
                  base.cavity->sample_spacing, samples.size(), o.mean, o.std, o.max, ms);
      std::fflush(stdout);
    }
  }
}
