// mtcs bench thermal: the thermal tiers' error against their run time, on random layouts, with
// the finite-volume solve at a fine cell as the truth (experiments/thermal).

#include "bench_thermal.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <numeric>

#include "bench_evaluate.h"
#include "mtcs/eval/thermal_model.h"
#include "mtcs/mold/decoder.h"
#include "mtcs/mold/scene.h"
#include "mtcs/opt/rng.h"
#include "mtcs/thermal/finite_volume.h"
#include "mtcs/thermal/line_sinks.h"

namespace mtcs::bench {
namespace {

using geometry::Vec3;
using thermal::Channel;

struct Case {
  thermal::Setting setting;
  thermal::Samples samples;
  std::vector<std::vector<Channel>> layouts;
};

// shared/cases/thermal/block3d_case.txt: a 120 x 80 x 60 mm block, 0.05 W/mm^2 into the patch
// 30..90 x 16..64 on z = 60, every other face 1e-5 W/(mm^2 K) to 25 C, k = 0.03 W/(mm K),
// bores at 40 C; the 720 samples of patch_samples.csv. Layouts: 2-5 through-bores along x,
// diameters 6-12 mm, walls at least 1 mm from the faces and from each other.
Case block_case(int count, std::uint64_t seed) {
  Case c;
  c.setting.block = {Vec3(0, 0, 0), Vec3(120, 80, 60)};
  c.setting.conductivity = 0.03;
  for (auto& f : c.setting.faces) f = {1e-5, 25};
  const Vec3 a(30, 16, 60), b(90, 16, 60), d(90, 64, 60), e(30, 64, 60);
  // Counter-clockwise seen from the melt (above the face).
  c.setting.heat_in = {{a, b, d, 0.05}, {a, d, e, 0.05}};
  for (int j = 0; j < 24; ++j)
    for (int i = 0; i < 30; ++i) c.samples.points.emplace_back(31 + 2 * i, 17 + 2 * j, 60), c.samples.weights.push_back(4);
  opt::Rng rng(seed);
  while (int(c.layouts.size()) < count) {
    const int n = 2 + rng.below(4);
    std::vector<Channel> layout;
    for (int tries = 0; int(layout.size()) < n && tries < 1000; ++tries) {
      const double r = (6 + 2 * rng.below(4)) / 2.0;
      const double y = r + 1 + rng.uniform() * (80 - 2 * r - 2), z = r + 1 + rng.uniform() * (60 - 2 * r - 2);
      bool apart = true;
      for (const Channel& o : layout)
        apart = apart && std::hypot(o.axis.p0.y() - y, o.axis.p0.z() - z) >= o.radius + r + 1;
      if (apart) layout.push_back({{Vec3(0, y, z), Vec3(120, y, z)}, r, 40, std::numeric_limits<double>::infinity()});
    }
    if (int(layout.size()) == n) c.layouts.push_back(std::move(layout));
  }
  return c;
}

// A mold: its setting and samples; layouts of random genomes (3 circuits of 4 legs), decoded.
Case mold_case(const std::string& path, int count, std::uint64_t seed) {
  const mold::Scene scene(mold::load_mold_spec(path));
  Case c{eval::thermal_setting(scene), eval::thermal_samples(scene), {}};
  for (const auto& g : random_genomes(scene, count, 3, 4, seed))
    c.layouts.push_back(eval::thermal_channels(mold::decode(scene, g), scene.spec()));
  return c;
}

// The layout with its first channel moved 0.5 mm sideways: what one mutation changes.
std::vector<Channel> nudged(std::vector<Channel> layout) {
  const Vec3 axis = layout[0].axis.p1 - layout[0].axis.p0;
  const Vec3 side = axis.unitOrthogonal() * 0.5;
  layout[0].axis.p0 += side, layout[0].axis.p1 += side;
  return layout;
}

struct Tier {
  std::string name;      // t0, t1, t2, t2d, fd
  int elements = 0;      // line sinks
  double cell = 0;       // fd
};

struct Row {
  Tier tier;
  double ms_full = 0, ms_incremental = 0, rms = 0, max = 0;
  double tau_std = 0, tau_mean = 0, tau_better_half = 0;
  int top10 = 0;
};

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
  return v[v.size() / 2];
}

// Kendall's tau-b of two rankings over the entries `which`.
double kendall(const std::vector<double>& a, const std::vector<double>& b, const std::vector<std::size_t>& which) {
  double concordant = 0, discordant = 0, ties_a = 0, ties_b = 0;
  for (std::size_t i = 0; i < which.size(); ++i)
    for (std::size_t j = i + 1; j < which.size(); ++j) {
      const double da = a[which[i]] - a[which[j]], db = b[which[i]] - b[which[j]];
      if (da == 0 && db == 0) continue;
      if (da == 0) ties_a += 1;
      else if (db == 0) ties_b += 1;
      else (da * db > 0 ? concordant : discordant) += 1;
    }
  const double n = concordant + discordant;
  const double denominator = std::sqrt((n + ties_a) * (n + ties_b));
  return denominator > 0 ? (concordant - discordant) / denominator : 0;
}

// Tier 0, the wall-distance objective `uniformity` (eval/thermal_stage.cpp): RMS over the
// samples of (distance to the nearest bore wall - 2 D of that bore). A ranking score only.
double wall_distance_uniformity(const std::vector<Channel>& layout, const thermal::Samples& samples) {
  double sum = 0, total = 0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    double best = std::numeric_limits<double>::infinity(), diameter = 0;
    for (const Channel& c : layout) {
      const Vec3 d = c.axis.p1 - c.axis.p0, p = samples.points[i] - c.axis.p0;
      const double t = std::clamp(p.dot(d) / d.squaredNorm(), 0.0, 1.0);
      const double e = (p - t * d).norm() - c.radius;
      if (e < best) best = e, diameter = 2 * c.radius;
    }
    sum += samples.weights[i] * (best - 2 * diameter) * (best - 2 * diameter);
    total += samples.weights[i];
  }
  return std::sqrt(sum / total);
}

// Temperatures of every layout by one tier, with its times per layout.
struct Scored {
  std::vector<std::vector<double>> temperature;  // empty for t0
  std::vector<double> score_std, score_mean, ms_full, ms_incremental;
};

Scored score(const Case& c, const Tier& tier) {
  Scored s;
  for (const auto& layout : c.layouts) {
    std::vector<double> t;
    if (tier.name == "t0") {
      const auto t0 = std::chrono::steady_clock::now();
      const double u = wall_distance_uniformity(layout, c.samples);
      s.ms_full.push_back(1e3 * seconds_since(t0));
      s.score_std.push_back(u), s.score_mean.push_back(u);
      continue;
    }
    if (tier.name == "fd") {
      thermal::FvOptions options;
      options.cell = tier.cell;
      const auto t0 = std::chrono::steady_clock::now();
      t = thermal::solve_finite_volume({c.setting, layout}, c.samples, options).temperature;
      s.ms_full.push_back(1e3 * seconds_since(t0));
    }
    const thermal::Summary sum = thermal::summarize(t, c.samples);
    s.temperature.push_back(t);
    s.score_std.push_back(sum.std), s.score_mean.push_back(sum.mean);
  }
  return s;
}

Scored score_line_sinks(const Case& c, const Tier& tier, int repeat) {
  thermal::LineSinkOptions options;
  options.tier = tier.name == "t1" ? thermal::Tier::T1 : tier.name == "t2" ? thermal::Tier::T2 : thermal::Tier::T2d;
  options.elements = tier.elements;
  const thermal::LineSinkModel model(c.setting, c.samples, options);
  Scored s;
  for (const auto& layout : c.layouts) {
    std::vector<double> full, incremental;
    std::vector<double> t;
    const auto moved = nudged(layout), moved_again = nudged(moved);
    for (int k = 0; k < repeat; ++k) {
      thermal::LineSinkCache cache;
      auto t0 = std::chrono::steady_clock::now();
      t = model.temperatures(layout, cache);
      full.push_back(1e3 * seconds_since(t0));
      // From the layout to its neighbour and on to the next: each solve has one channel new (going
      // back would find the layout's blocks still cached: a hit, not an incremental evaluation).
      t0 = std::chrono::steady_clock::now();
      model.temperatures(moved, cache);
      incremental.push_back(1e3 * seconds_since(t0));
      t0 = std::chrono::steady_clock::now();
      model.temperatures(moved_again, cache);
      incremental.push_back(1e3 * seconds_since(t0));
    }
    s.ms_full.push_back(median(full));
    s.ms_incremental.push_back(median(incremental));
    const thermal::Summary sum = thermal::summarize(t, c.samples);
    s.temperature.push_back(std::move(t));
    s.score_std.push_back(sum.std), s.score_mean.push_back(sum.mean);
  }
  return s;
}

Row judge(const Tier& tier, const Scored& s, const Scored& ref) {
  Row r{tier};
  r.ms_full = median(s.ms_full);
  r.ms_incremental = s.ms_incremental.empty() ? r.ms_full : median(s.ms_incremental);
  const std::size_t n = ref.score_std.size();
  if (!s.temperature.empty()) {
    double sq = 0, count = 0;
    for (std::size_t l = 0; l < n; ++l)
      for (std::size_t i = 0; i < ref.temperature[l].size(); ++i) {
        const double d = s.temperature[l][i] - ref.temperature[l][i];
        sq += d * d, count += 1, r.max = std::max(r.max, std::abs(d));
      }
    r.rms = std::sqrt(sq / count);
  } else {
    r.rms = r.max = std::nan("");
  }
  std::vector<std::size_t> all(n);
  std::iota(all.begin(), all.end(), 0);
  r.tau_std = kendall(s.score_std, ref.score_std, all);
  r.tau_mean = kendall(s.score_mean, ref.score_mean, all);
  // The better half by the reference's std: where an optimiser spends its time.
  std::vector<std::size_t> by_ref = all, by_tier = all;
  std::sort(by_ref.begin(), by_ref.end(), [&](auto a, auto b) { return ref.score_std[a] < ref.score_std[b]; });
  std::sort(by_tier.begin(), by_tier.end(), [&](auto a, auto b) { return s.score_std[a] < s.score_std[b]; });
  r.tau_better_half = kendall(s.score_std, ref.score_std, {by_ref.begin(), by_ref.begin() + std::ptrdiff_t(n / 2)});
  const std::size_t top = std::min<std::size_t>(10, n);
  for (std::size_t i = 0; i < top; ++i)
    r.top10 += int(std::find(by_tier.begin(), by_tier.begin() + std::ptrdiff_t(top), by_ref[i]) != by_tier.begin() + std::ptrdiff_t(top));
  return r;
}

std::string label(const Tier& t) {
  char buf[64];
  if (t.name == "fd") std::snprintf(buf, sizeof buf, "fd h=%g mm", t.cell);
  else if (t.elements > 0) std::snprintf(buf, sizeof buf, "%s M=%d", t.name.c_str(), t.elements);
  else return t.name;
  return buf;
}

}  // namespace

int bench_thermal(const ThermalBenchOptions& o) {
  const Case c = o.scene == "block" ? block_case(o.layouts, o.seed) : mold_case(o.scene, o.layouts, o.seed);
  std::cerr << "bench thermal: " << c.layouts.size() << " layouts, " << c.samples.size()
            << " samples; reference: finite volumes at " << o.reference_cell << " mm\n";
  const Tier reference{"fd", 0, o.reference_cell};
  const auto t0 = std::chrono::steady_clock::now();
  const Scored ref = score(c, reference);
  std::cerr << "  reference: " << seconds_since(t0) << " s\n";

  const std::vector<Tier> tiers = {{"t0"},       {"t1", 1},    {"t2", 4},    {"t2d", 2},  {"t2d", 4},
                                   {"t2d", 8},   {"t2d", 12},  {"fd", 0, 4}, {"fd", 0, 2}};
  std::vector<Row> rows;
  for (const Tier& t : tiers) {
    const auto t1 = std::chrono::steady_clock::now();
    const Scored s = t.name.rfind("t", 0) == 0 && t.name != "t0" ? score_line_sinks(c, t, o.repeat) : score(c, t);
    rows.push_back(judge(t, s, ref));
    std::cerr << "  " << label(t) << ": " << seconds_since(t1) << " s\n";
  }
  const std::string default_tier = "t2d M=4";
  if (o.json) {
    std::printf("{\"scene\": \"%s\", \"layouts\": %zu, \"samples\": %zu, \"reference\": \"fd h=%g mm\", \"default_tier\": \"%s\", \"tiers\": [",
                o.scene.c_str(), c.layouts.size(), c.samples.size(), o.reference_cell, default_tier.c_str());
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const Row& r = rows[i];
      auto num = [](double v) { return std::isfinite(v) ? std::to_string(v) : std::string("null"); };
      std::printf("%s\n  {\"tier\": \"%s\", \"elements\": %d, \"cell_mm\": %g, \"ms_full\": %.5f, \"ms_incremental\": %.5f, "
                  "\"rms_k\": %s, \"max_k\": %s, \"tau_std\": %.4f, \"tau_mean\": %.4f, \"tau_better_half\": %.4f, \"top10\": %d}",
                  i ? "," : "", label(r.tier).c_str(), r.tier.elements, r.tier.cell, r.ms_full, r.ms_incremental,
                  num(r.rms).c_str(), num(r.max).c_str(), r.tau_std, r.tau_mean, r.tau_better_half, r.top10);
    }
    std::printf("\n]}\n");
    return 0;
  }
  std::printf("tier,ms_full,ms_incremental,rms_k,max_k,tau_std,tau_mean,tau_better_half,top10\n");
  for (const Row& r : rows)
    std::printf("%s,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%d\n", label(r.tier).c_str(), r.ms_full, r.ms_incremental, r.rms,
                r.max, r.tau_std, r.tau_mean, r.tau_better_half, r.top10);
  return 0;
}

}  // namespace mtcs::bench
