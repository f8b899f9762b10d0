// mtcs bench thermal: the thermal tiers' error against their run time, on random layouts, with
// the finite-volume solve at a fine cell as the truth (experiments/thermal).

#include "bench_thermal.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <iostream>
#include <numeric>
#include <optional>

#include "bench_evaluate.h"
#include "mtcs/eval/across_part.h"
#include "mtcs/eval/part_sides.h"
#include "mtcs/eval/temperature_objectives.h"
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
  thermal::Samples samples;  // a mold's: the points across the part after the samples, unweighted
  std::vector<std::vector<Channel>> layouts;
  std::optional<mold::MoldSpec> spec;       // a mold: its cycle time and difference
  std::size_t count = 0;                    // the samples (the points across after them)
  std::vector<std::optional<Vec3>> across;  // per sample, the point across the part
  std::vector<eval::PartSide> sides;        // per sample, its half of the mold (cavity.parting)
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
  c.count = c.samples.size();
  return c;
}

// The least gap between a layout's bore walls and the samples (mm; < 0: a bore through the
// part). Samples lie <= sample_spacing * sqrt(3) / 2 apart, so a gap above that clears the wall.
double cavity_gap(const std::vector<Channel>& layout, const thermal::Samples& samples) {
  double gap = std::numeric_limits<double>::infinity();
  for (const Channel& ch : layout)
    for (const Vec3& p : samples.points) {
      const Vec3 d = ch.axis.p1 - ch.axis.p0, q = p - ch.axis.p0;
      const double t = std::clamp(q.dot(d) / d.squaredNorm(), 0.0, 1.0);
      gap = std::min(gap, (q - t * d).norm() - ch.radius);
    }
  return gap;
}

// A mold: its setting and samples; layouts of random genomes (`circuits` circuits of 4 legs),
// decoded; with `clear_of_part`, only those whose bores keep off the part (most random layouts
// of 3 circuits drill through a cup: not what an optimiser ranks); with `difference`, the points
// across the part after the samples.
Case mold_case(const std::string& path, int count, std::uint64_t seed, int circuits, bool clear_of_part,
               bool difference) {
  const mold::Scene scene(mold::load_mold_spec(path));
  Case c{eval::thermal_setting(scene), eval::thermal_samples(scene), {}, scene.spec(), 0, {}, {}};
  c.count = c.samples.size();
  c.sides = eval::part_sides(scene, c.samples);  // empty without cavity.parting (its tau NaN)
  const double spacing = scene.spec().thermal.sample_spacing.value_or(scene.spec().cavity->sample_spacing);
  for (std::uint64_t batch = 0; int(c.layouts.size()) < count; ++batch) {
    if (batch == 1000)
      throw std::runtime_error("bench thermal: fewer than " + std::to_string(count) +
                               " random layouts clear of the part in 1000 batches (try --circuits 1)");
    for (const auto& g : random_genomes(scene, count, circuits, 4, seed + batch)) {
      std::vector<Channel> layout = eval::thermal_channels(mold::decode(scene, g), scene.spec());
      if (clear_of_part && cavity_gap(layout, c.samples) < spacing) continue;
      if (int(c.layouts.size()) < count) c.layouts.push_back(std::move(layout));
    }
  }
  if (!difference) return c;
  // The points across the part join the samples, unweighted, as temperature_difference has them.
  c.across = eval::across_part(scene, c.samples, 3 * scene.spec().cavity->wall_thickness);
  if (std::none_of(c.across.begin(), c.across.end(), [](const auto& q) { return q.has_value(); }))
    c.across.clear();  // no faces pair across the part: no difference to rank (its tau NaN)
  eval::append_across(c.samples, c.across);
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
  double void_panel = 0; // line sinks: the part's void as panels this wide (mm; 0: none)
  int sample_images = 0;  // line sinks: image levels summed exactly at the samples (0: the model's choice)
};

struct Row {
  Tier tier;
  double ms_full = 0, ms_incremental = 0, rms = 0, max = 0;
  double tau_std = 0, tau_mean = 0, tau_max = 0, tau_better_half = 0;
  double tau_cycle = 0, tau_difference = 0;  // a mold's (NaN on the block)
  double tau_std_side = 0;                    // a parted mold's (NaN without cavity.parting)
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
  std::vector<std::vector<double>> temperature;  // at the samples; empty for t0
  std::vector<double> score_std, score_mean, score_max, score_cycle, score_difference, score_std_side, ms_full,
      ms_incremental;

  // The objectives of one layout's temperatures at the samples and the points across, as the
  // temperature stage computes them (a mold's at the nominal cycle's films: the bench does not
  // follow each layout's cycle).
  void add(const Case& c, std::vector<double> t) {
    const std::vector<double> at_across(t.begin() + std::ptrdiff_t(c.count), t.end());
    t.resize(c.count);
    const thermal::Summary sum = thermal::summarize(t, c.samples);
    score_std.push_back(sum.std), score_mean.push_back(sum.mean), score_max.push_back(sum.max);
    if (c.spec) {
      score_cycle.push_back(eval::temperature_objectives(t, c.samples, *c.spec).cycle_time);
      if (!c.across.empty()) score_difference.push_back(eval::wall_difference(t, at_across, c.samples, c.across).mean);
      if (!c.sides.empty()) score_std_side.push_back(eval::side_summaries(t, c.samples, c.sides).larger_std());
    }
    temperature.push_back(std::move(t));
  }
  void add_score(double u) {  // t0: one ranking score for every objective
    for (auto* v : {&score_std, &score_mean, &score_max, &score_cycle, &score_difference, &score_std_side}) v->push_back(u);
  }
};

Scored score(const Case& c, const Tier& tier) {
  Scored s;
  // The finite volumes take seconds to minutes a layout on a mold: say how far they are.
  const auto start = std::chrono::steady_clock::now();
  auto said = start;
  for (const auto& layout : c.layouts) {
    if (tier.name == "fd" && !s.ms_full.empty() && seconds_since(said) > 10) {
      said = std::chrono::steady_clock::now();
      const double spent = seconds_since(start), done = double(s.ms_full.size());
      std::fprintf(stderr, "  fd h=%g mm: %zu of %zu layouts in %.0f s, ~%.0f s left\n", tier.cell, s.ms_full.size(),
                   c.layouts.size(), spent, spent / done * (double(c.layouts.size()) - done));
    }
    std::vector<double> t;
    if (tier.name == "t0") {
      const auto t0 = std::chrono::steady_clock::now();
      const double u = wall_distance_uniformity(layout, c.samples);
      s.ms_full.push_back(1e3 * seconds_since(t0));
      s.add_score(u);
      continue;
    }
    if (tier.name == "fd") {
      thermal::FvOptions options;
      options.cell = tier.cell;
      const auto t0 = std::chrono::steady_clock::now();
      t = thermal::solve_finite_volume({c.setting, layout}, c.samples, options).temperature;
      s.ms_full.push_back(1e3 * seconds_since(t0));
    }
    s.add(c, std::move(t));
  }
  return s;
}

Scored score_line_sinks(const Case& c, const Tier& tier, int repeat) {
  thermal::LineSinkOptions options;
  options.tier = tier.name == "t1" ? thermal::Tier::T1 : tier.name == "t2" ? thermal::Tier::T2 : thermal::Tier::T2d;
  options.elements = tier.elements;
  options.void_panel = tier.void_panel;
  if (tier.sample_images > 0) options.sample_images = tier.sample_images;
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
    s.add(c, std::move(t));
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
  r.tau_max = kendall(s.score_max, ref.score_max, all);
  r.tau_cycle = ref.score_cycle.empty() ? std::nan("") : kendall(s.score_cycle, ref.score_cycle, all);
  r.tau_difference = ref.score_difference.empty() ? std::nan("") : kendall(s.score_difference, ref.score_difference, all);
  r.tau_std_side = ref.score_std_side.empty() ? std::nan("") : kendall(s.score_std_side, ref.score_std_side, all);
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
  else if (t.void_panel > 0) std::snprintf(buf, sizeof buf, "%s M=%d void %g mm", t.name.c_str(), t.elements, t.void_panel);
  else if (t.elements > 0) std::snprintf(buf, sizeof buf, "%s M=%d", t.name.c_str(), t.elements);
  else return t.name;
  std::string s = buf;
  if (t.sample_images > 0) s += " S=" + std::to_string(t.sample_images);
  return s;
}

constexpr double kMaxFvCells = 30e6;

// Why a reference at `cell` is too fine for the block, naming a cell that fits; nothing when it
// fits.
std::optional<std::string> too_fine(const geometry::Box& block, double cell) {
  const geometry::Vec3 size = block.size();
  auto cells_at = [&](double h) {
    return thermal::fv_cells_along(size.x(), h) * thermal::fv_cells_along(size.y(), h) *
           thermal::fv_cells_along(size.z(), h);
  };
  const double cells = cells_at(cell);
  if (cells <= kMaxFvCells) return std::nullopt;
  double coarser = std::ceil(cell * std::cbrt(cells / kMaxFvCells) * 100) / 100;  // rounding may leave it too fine
  while (cells_at(coarser) > kMaxFvCells) coarser += 0.01;
  char buf[320];
  std::snprintf(buf, sizeof buf,
                "--reference-cell: %g mm makes %.1f M cells of the %g x %g x %g mm block (at most %.0f M); "
                "use %.2f mm or coarser",
                cell, cells * 1e-6, size.x(), size.y(), size.z(), kMaxFvCells * 1e-6, coarser);
  return std::string(buf);
}

}  // namespace

int bench_thermal(const ThermalBenchOptions& o) {
  const Case c = o.scene == "block" ? block_case(o.layouts, o.seed)
                                    : mold_case(o.scene, o.layouts, o.seed, o.circuits, !o.through_part, o.difference);
  // A reference of more than 30 M cells is refused before the solves: the finite volumes'
  // memory and time a layout grow with the cells (the plate's block at 1 mm has 7.2 M and took
  // ~4 min a layout here).
  if (const std::optional<std::string> why = too_fine(c.setting.block, o.reference_cell)) {
    std::cerr << "mtcs bench thermal: " << *why << "\n";
    return 2;
  }
  std::cerr << "bench thermal: " << c.layouts.size() << " layouts, " << c.count << " samples ("
            << c.samples.size() - c.count << " across the part); reference: finite volumes at " << o.reference_cell << " mm\n";
  const Tier reference{"fd", 0, o.reference_cell};
  const auto t0 = std::chrono::steady_clock::now();
  const Scored ref = score(c, reference);
  std::cerr << "  reference: " << seconds_since(t0) << " s\n";

  std::vector<Tier> tiers = {{"t0"},       {"t1", 1},    {"t2", 4},    {"t2d", 2},  {"t2d", 4},
                             {"t2d", 8},   {"t2d", 12},  {"fd", 0, 4}, {"fd", 0, 2}};
  // A cavity in the block: also the line sinks that know its void (thermal.cavity_void: surface).
  if (c.setting.cavity_mesh || c.setting.cavity_box)
    for (const double panel : o.void_panels) tiers.insert(tiers.begin() + 5, Tier{"t2d", 4, 0, panel});
  // The coupled cavity condition (a film on the cavity's wall) reaches the line sinks through
  // the void's panels only: the tiers blind to the void cannot model it.
  const bool films = std::any_of(c.setting.heat_in.begin(), c.setting.heat_in.end(),
                                 [](const thermal::HeatedTriangle& t) { return t.film > 0; });
  if (films && (c.setting.cavity_mesh || c.setting.cavity_box)) {
    std::erase_if(tiers, [](const Tier& t) { return t.name != "t0" && t.name != "fd" && t.void_panel == 0; });
    std::cerr << "  the coupled cavity: the line sinks with the void's panels only\n";
  }
  for (const int levels : o.sample_images) {
    const std::size_t n = tiers.size();
    for (std::size_t i = 0; i < n; ++i)
      if (tiers[i].name != "t0" && tiers[i].name != "fd") {
        Tier t = tiers[i];
        t.sample_images = levels;
        tiers.push_back(t);
      }
  }
  if (!o.tiers.empty())  // only those asked for, by the start of their labels
    std::erase_if(tiers, [&](const Tier& t) {
      return std::none_of(o.tiers.begin(), o.tiers.end(), [&](const std::string& w) { return label(t).rfind(w, 0) == 0; });
    });
  std::vector<Row> rows;
  for (const Tier& t : tiers) {
    const auto t1 = std::chrono::steady_clock::now();
    // The reference's own cell: the reference (not solved twice), its time per layout apart.
    const Scored s = t.name == "fd" && t.cell == o.reference_cell ? ref
                     : t.name.rfind("t", 0) == 0 && t.name != "t0" ? score_line_sinks(c, t, o.repeat)
                                                                    : score(c, t);
    rows.push_back(judge(t, s, ref));
    std::cerr << "  " << label(t) << ": " << seconds_since(t1) << " s\n";
  }
  const std::string default_tier = "t2d M=4";
  if (o.json) {
    std::printf("{\"scene\": \"%s\", \"layouts\": %zu, \"samples\": %zu, \"reference\": \"fd h=%g mm\", \"default_tier\": \"%s\", \"tiers\": [",
                o.scene.c_str(), c.layouts.size(), c.count, o.reference_cell, default_tier.c_str());
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const Row& r = rows[i];
      auto num = [](double v) { return std::isfinite(v) ? std::to_string(v) : std::string("null"); };
      std::printf("%s\n  {\"tier\": \"%s\", \"elements\": %d, \"cell_mm\": %g, \"ms_full\": %.5f, \"ms_incremental\": %.5f, "
                  "\"rms_k\": %s, \"max_k\": %s, \"tau_std\": %.4f, \"tau_mean\": %.4f, \"tau_max\": %.4f, \"tau_better_half\": %.4f, \"top10\": %d, "
                  "\"tau_cycle\": %s, \"tau_difference\": %s, \"tau_std_side\": %s}",
                  i ? "," : "", label(r.tier).c_str(), r.tier.elements, r.tier.cell, r.ms_full, r.ms_incremental,
                  num(r.rms).c_str(), num(r.max).c_str(), r.tau_std, r.tau_mean, r.tau_max, r.tau_better_half, r.top10,
                  num(r.tau_cycle).c_str(), num(r.tau_difference).c_str(), num(r.tau_std_side).c_str());
    }
    std::printf("\n]}\n");
    return 0;
  }
  std::printf("tier,ms_full,ms_incremental,rms_k,max_k,tau_std,tau_mean,tau_max,tau_better_half,top10,tau_cycle,tau_difference,"
              "tau_std_side\n");
  for (const Row& r : rows)
    std::printf("%s,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%d,%.4f,%.4f,%.4f\n", label(r.tier).c_str(), r.ms_full,
                r.ms_incremental, r.rms, r.max, r.tau_std, r.tau_mean, r.tau_max, r.tau_better_half, r.top10, r.tau_cycle,
                r.tau_difference, r.tau_std_side);
  return 0;
}

}  // namespace mtcs::bench
