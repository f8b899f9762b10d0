// A cold T2d solve of small plate layouts (what an ES child on the plate mostly is: ~3 of its
// ~4 bores new, so nearly every channel and pair block is built): the same 80 random layouts
// (40 of one circuit x 4 bores, 40 of two x 2) solved with a fresh cache each, ROUNDS times;
// prints the best and median round's microseconds per solve and a checksum of the std
// objective (equal between two binaries whose solves agree bit for bit).
//
//   (build: as plate_samples.cpp, see plate_wall_images.md)
//   ./plate_cold_solve molds/plate.yaml [ROUNDS]

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "bench/bench_evaluate.h"
#include "mtcs/eval/temperature_objectives.h"
#include "mtcs/eval/thermal_model.h"
#include "mtcs/mold/decoder.h"
#include "mtcs/mold/scene.h"
#include "mtcs/thermal/line_sinks.h"

using namespace mtcs;

int main(int argc, char** argv) {
  if (argc < 2) return std::fprintf(stderr, "usage: plate_cold_solve MOLD [ROUNDS]\n"), 2;
  const int rounds = argc > 2 ? std::atoi(argv[2]) : 15;
  const mold::MoldSpec spec = mold::load_mold_spec(argv[1]);
  const mold::Scene scene(spec);
  std::vector<mold::Genome> genomes = bench::random_genomes(scene, 40, 1, 4, 1);
  for (const auto& g : bench::random_genomes(scene, 40, 2, 2, 2)) genomes.push_back(g);
  const thermal::Setting setting = eval::thermal_setting(scene);
  const thermal::Samples samples = eval::thermal_samples(scene);
  thermal::LineSinkOptions options;
  options.elements = spec.thermal.elements_per_bore;
  options.images = spec.thermal.wall_images;
  const thermal::LineSinkModel model(setting, samples, options);
  std::vector<std::vector<thermal::Channel>> layouts;
  std::size_t bores = 0;
  for (const auto& g : genomes) {
    layouts.push_back(eval::thermal_channels(mold::decode(scene, g), spec));
    bores += layouts.back().size();
  }
  double checksum = 0;
  std::vector<double> us;
  for (int r = 0; r < rounds; ++r) {
    double sum = 0;
    const auto t0 = std::chrono::steady_clock::now();
    for (const auto& channels : layouts) {
      thermal::LineSinkCache cache;
      sum += eval::temperature_objectives(model.temperatures(channels, cache), samples, spec).std;
    }
    us.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count() /
                 double(layouts.size()));
    checksum = sum;
  }
  std::sort(us.begin(), us.end());
  std::printf("layouts %zu, bores %.2f per layout, best %.1f us, median %.1f us per cold solve, checksum %.17g\n",
              layouts.size(), double(bores) / double(layouts.size()), us.front(), us[us.size() / 2], checksum);
}
