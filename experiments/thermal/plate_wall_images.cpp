// The plate's T2d with fewer reflection levels summed exactly at the bores' walls
// (LineSinkOptions::images 2, the default, against 1: the rest joins the far lattice there): the
// temperature objectives per layout and the time of a cold solve, to rank against T3 (the fd3
// rows of plate_samples.csv). Layouts: as plate_samples.cpp (random genomes, ES results).
//
//   (build: as plate_samples.cpp, see plate_wall_images.md)
//   ./plate_wall_images molds/plate.yaml experiments/thermal/es_plate_layouts/*.layout.yaml > out.csv

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "bench/bench_evaluate.h"
#include "mtcs/eval/temperature_objectives.h"
#include "mtcs/eval/thermal_model.h"
#include "mtcs/mold/decoder.h"
#include "mtcs/mold/layout_io.h"
#include "mtcs/mold/scene.h"
#include "mtcs/thermal/line_sinks.h"
#include "mtcs/thermal/void_plane.h"

using namespace mtcs;

struct Named {
  std::string set, name;
  mold::Genome genome;
};

int main(int argc, char** argv) {
  if (argc < 2) return std::fprintf(stderr, "usage: plate_wall_images MOLD [LAYOUT.yaml...]\n"), 2;
  const mold::MoldSpec spec = mold::load_mold_spec(argv[1]);
  const mold::Scene scene(spec);
  std::vector<Named> layouts;
  auto add = [&](const std::string& set, const std::vector<mold::Genome>& g) {
    for (std::size_t i = 0; i < g.size(); ++i) layouts.push_back({set, set + "-" + std::to_string(i), g[i]});
  };
  add("random3x4", bench::random_genomes(scene, 60, 3, 4, 1));
  add("random2x3", bench::random_genomes(scene, 30, 2, 3, 2));
  add("random1x3", bench::random_genomes(scene, 30, 1, 3, 3));
  for (int a = 2; a < argc; ++a) {
    const std::filesystem::path p(argv[a]);
    layouts.push_back({"es:" + p.parent_path().filename().string(), p.filename().string(), mold::load_layout(p, spec)});
  }
  const thermal::Setting setting = eval::thermal_setting(scene);
  const thermal::Samples samples = eval::thermal_samples(scene);
  const thermal::CavityCut cut = spec.thermal.void_plane ? thermal::cut_at_cavity_void(setting) : thermal::CavityCut{setting};
  std::printf("set,layout,wall_images,samples,mean,std,max,ms\n");
  for (const int images : {2, 1}) {
    thermal::LineSinkOptions options;
    options.elements = spec.thermal.elements_per_bore;
    options.images = images;
    const thermal::LineSinkModel model(cut.setting, samples, options);
    for (const Named& l : layouts) {
      const auto channels = cut.fold(eval::thermal_channels(mold::decode(scene, l.genome), spec));
      thermal::LineSinkCache cache;  // cold: every channel and pair built
      const auto t0 = std::chrono::steady_clock::now();
      const eval::TemperatureObjectives o = eval::temperature_objectives(model.temperatures(channels, cache), samples, spec);
      const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      std::printf("%s,%s,%d,%zu,%.9g,%.9g,%.9g,%.3f\n", l.set.c_str(), l.name.c_str(), images, samples.size(), o.mean,
                  o.std, o.max, ms);
      std::fflush(stdout);
    }
  }
}
