#include "mtcs/eval/cavity_temperature.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <sstream>

#include "mtcs/eval/across_part.h"
#include "mtcs/eval/cycle_time.h"
#include "mtcs/eval/part_coupling.h"
#include "mtcs/eval/temperature_objectives.h"
#include "mtcs/eval/thermal_model.h"
#include "mtcs/eval/thermal_tiers.h"
#include "mtcs/geometry/segment_distance.h"
#include "mtcs/io/input_error.h"
#include "mtcs/io/points_csv.h"
#include "mtcs/thermal/finite_volume.h"
#include "mtcs/thermal/line_sinks.h"
#include "mtcs/thermal/void_plane.h"

namespace mtcs::eval {
namespace {

using geometry::Vec3;

// The heated triangles as one mesh (shared corners merged): the cavity surface as the thermal
// model sees it.
mesh::TriangleMesh heated_surface(const thermal::Setting& setting) {
  mesh::TriangleMesh m;
  std::map<std::array<double, 3>, int> index;
  auto vertex = [&](const Vec3& p) {
    auto [it, fresh] = index.try_emplace({p.x(), p.y(), p.z()}, int(m.vertices.size()));
    if (fresh) m.vertices.push_back(p);
    return it->second;
  };
  for (const auto& t : setting.heat_in) m.triangles.push_back({vertex(t.a), vertex(t.b), vertex(t.c)});
  return m;
}

std::string describe(const geometry::Box& b) {
  std::ostringstream s;
  s << "x " << b.min.x() << ".." << b.max.x() << ", y " << b.min.y() << ".." << b.max.y() << ", z " << b.min.z() << ".."
    << b.max.z() << " mm";
  return s.str();
}

}  // namespace

// Solves of the coupled cycle's fixed point (mtcs thermal), at most.
constexpr int kCycleIterations = 6;
// A field's vertices per line-sink model (memory: one row of the void's potentials each).
constexpr std::size_t kFieldChunk = 4096;

CavityConditionUsed cavity_condition_used(const mold::MoldSpec& spec) {
  CavityConditionUsed c;
  c.model = mold::to_string(spec.thermal.cavity_condition);
  c.melt_temperature = spec.thermal.polymer.melt_temperature;
  if (spec.thermal.cavity_condition == mold::CavityCondition::Coupled) {
    const PartCoupling p = cavity_coupling(spec);
    const CycleTimes times = nominal_cycle(spec);
    c.part_film = p.film * 1e6, c.part_temperature = p.temperature;
    c.in_mold = times.in_mold, c.cycle = times.cycle;
    c.wall_thinnest = c.wall_thickest = spec.cavity ? spec.cavity->wall_thickness : mold::Cavity{}.wall_thickness;
    c.local_wall = spec.cavity && spec.cavity->local_thickness;
  } else {
    c.heat_flux = cavity_heat_flux(spec) * 1e6;
  }
  return c;
}

ThermalQuery thermal_query(const mold::MoldSpec& spec) {
  return {spec.thermal.tier, spec.thermal.elements_per_bore, spec.thermal.wall_images, spec.thermal.cell_size};
}

namespace {

// One solve with `spec`'s thermal section (the scene's, or another cycle's) at the scene's samples.
CavityTemperature solve_once(const mold::Scene& scene, const mold::MoldSpec& spec, const mold::Layout& layout,
                             const ThermalQuery& query, const thermal::Samples& samples, const std::vector<Vec3>& points,
                             double field_edge) {
  const auto t0 = std::chrono::steady_clock::now();
  const thermal::Setting setting = thermal_setting(scene, spec);
  const std::vector<thermal::Channel> channels = thermal_channels(layout, spec);
  CavityTemperature out;
  out.tier = mold::to_string(query.tier);
  out.condition = cavity_condition_used(spec);
  if (out.condition.local_wall && !samples.thickness.empty()) {  // the samples' walls with the triangles'
    const auto [thinnest, thickest] = std::minmax_element(samples.thickness.begin(), samples.thickness.end());
    const std::vector<double>& triangles = scene.cavity_thickness();
    out.condition.wall_thinnest =
        triangles.empty() ? *thinnest : std::min(*thinnest, *std::min_element(triangles.begin(), triangles.end()));
    out.condition.wall_thickest = std::max(*thickest, out.condition.wall_thickest);
  }
  out.surface = mold::to_string(spec.thermal.objective_surface);
  if (field_edge > 0) out.field = {mesh::refine(heated_surface(setting), field_edge), {}, "temperature", "degC"};

  // The extra points and the field's vertices after the samples (weights matter only for the
  // samples' summary).
  std::vector<double> t;
  if (query.tier == mold::ThermalTier::Fd) {
    thermal::Samples extra;
    for (const Vec3& p : points) extra.points.push_back(p), extra.weights.push_back(0);
    for (const Vec3& p : out.field.surface.vertices) extra.points.push_back(p), extra.weights.push_back(0);
    thermal::Samples all = samples;
    all.points.insert(all.points.end(), extra.points.begin(), extra.points.end());
    all.weights.insert(all.weights.end(), extra.weights.begin(), extra.weights.end());
    thermal::FvOptions options;
    options.cell = query.cell;
    const thermal::FvResult r = thermal::solve_finite_volume({setting, channels}, all, options);
    t = r.temperature;
    out.balance = {r.heat_in, r.heat_to_channels, r.heat_to_faces};
    out.bore_heat = r.heat_to_channel;
  } else {
    thermal::LineSinkOptions options;
    options.tier = line_sink_tier(query.tier);
    options.elements = query.elements;
    options.images = query.wall_images;
    options.void_panel = spec.thermal.void_panel;
    const thermal::CavityCut cut =
        spec.thermal.void_plane ? thermal::cut_at_cavity_void(setting) : thermal::CavityCut{setting};
    const std::vector<thermal::Channel> folded = cut.fold(channels);
    // The samples in a model of their own, the extra points in another: the line sinks' float
    // coordinates (from the samples' centre) and far-expansion chunks (16 neighbouring targets)
    // depend on which points share the set, so the samples' values stay those of the thermal
    // command bit for bit whatever else is asked. The system solved does not depend on them,
    // and the second model shares the first's void (its build).
    const thermal::LineSinkModel model(cut.setting, samples, options);
    thermal::LineSinkCache cache;
    const thermal::LineSinkSolution r = model.solve(folded, cache);
    t = r.temperature;
    // The points asked for (and those across the part) in one model, as without a field; the
    // field's vertices in models of kFieldChunk each, none kept: a model holds a dense row per
    // point and panel (the gear's 34 600 vertices and 911 panels: 380 MB at once).
    const auto add_at = [&](std::span<const Vec3> at, bool keep) {
      thermal::Samples set;
      for (const Vec3& p : at) set.points.push_back(p), set.weights.push_back(0);
      const thermal::LineSinkModel at_extra(model, set, keep);
      thermal::LineSinkCache extra_cache;
      const std::vector<double> te = at_extra.temperatures(folded, extra_cache);
      t.insert(t.end(), te.begin(), te.end());
    };
    if (!points.empty()) add_at(points, true);
    const std::span<const Vec3> field = out.field.surface.vertices;
    for (std::size_t i = 0; i < field.size(); i += kFieldChunk)
      add_at(field.subspan(i, std::min(kFieldChunk, field.size() - i)), false);
    double to_channels = 0;
    for (double q : r.channel_heat) to_channels += q;
    out.balance = {r.heat_in, to_channels, r.face_heat};
    out.bore_heat = cut.unfold_heat(channels, r.channel_heat);  // a bore the cut splits is two channels
  }
  const std::size_t n = samples.size(), m = points.size();
  out.at_samples.assign(t.begin(), t.begin() + std::ptrdiff_t(n));
  out.at_points.assign(t.begin() + std::ptrdiff_t(n), t.begin() + std::ptrdiff_t(n + m));
  out.field.values.assign(t.begin() + std::ptrdiff_t(n + m), t.end());
  out.summary = thermal::summarize(out.at_samples, samples);
  if (n > 0) out.hottest = samples.points[out.summary.hottest];
  const TemperatureObjectives objectives = temperature_objectives(out.at_samples, samples, spec);
  const mold::ThermalSpec& thermal = spec.thermal;
  out.cycle_time = objectives.cycle_time;
  out.cooling_time = thermal.cavity_condition == mold::CavityCondition::Coupled
                         ? out.cycle_time - thermal.cycle.fill - thermal.cycle.pack - thermal.cycle.open
                         : out.cycle_time;
  out.ejectable = out.summary.max < thermal.polymer.eject_temperature;
  if (n > 0) {
    const std::size_t k = slowest_place(out.at_samples, samples.thickness, thermal.polymer, n);
    out.slowest = samples.points[k];
    out.slowest_wall = samples.thickness.empty() ? (spec.cavity ? spec.cavity->wall_thickness : mold::Cavity{}.wall_thickness)
                                                 : samples.thickness[k];
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace

// Splits the points asked for from those across the part (after them); the summaries of the
// part's two faces: the difference across its wall and, with the mold's parting, each side's.
void summarize_faces(const mold::Scene& scene, CavityTemperature& r, std::size_t asked, const thermal::Samples& samples,
                     const std::vector<std::optional<Vec3>>& across) {
  const std::vector<double> at_across(r.at_points.begin() + std::ptrdiff_t(asked), r.at_points.end());
  r.at_points.resize(asked);
  r.across = wall_difference(r.at_samples, at_across, samples, across);
  if (const std::vector<PartSide> sides = part_sides(scene, samples); !sides.empty())
    r.sides = side_summaries(r.at_samples, samples, sides);
}

CavityTemperature cavity_temperature(const mold::Scene& scene, const mold::Layout& layout, const ThermalQuery& query,
                                     const std::vector<Vec3>& asked, double field_edge) {
  const auto start = std::chrono::steady_clock::now();
  // The points across the part join the points asked for.
  const thermal::Samples samples = thermal_samples(scene);
  const double reach = 3 * (scene.spec().cavity ? scene.spec().cavity->wall_thickness : 0.0);
  const std::vector<std::optional<Vec3>> across = across_part(scene, samples, reach);
  std::vector<Vec3> points = asked;
  for (const auto& q : across)
    if (q) points.push_back(*q);
  CavityTemperature r = solve_once(scene, scene.spec(), layout, query, samples, points, field_edge);
  const mold::ThermalSpec& t = scene.spec().thermal;
  if (t.cavity_condition != mold::CavityCondition::Coupled || t.cycle.cooling || t.part_film) {
    summarize_faces(scene, r, asked.size(), samples, across);
    r.circuits = coolant_circuits(layout, scene.spec(), r.bore_heat);
    return r;
  }
  // The film was derived for the nominal cycle; the solution needs its own: the cooling time
  // whose film gives a solution needing that cooling time, within 1 % (consistent_cooling),
  // unless the part cannot be ejected at the nominal film.
  if (r.ejectable) {
    mold::MoldSpec spec = scene.spec();
    std::vector<std::pair<double, CavityTemperature>> solved{{nominal_cycle(spec).cooling, r}};
    const auto need = [&](double cooling) {
      for (const auto& [c, s] : solved)
        if (c == cooling) return s.cooling_time;
      spec.thermal.cycle.cooling = cooling;
      solved.emplace_back(cooling, solve_once(scene, spec, layout, query, samples, points, field_edge));
      return solved.back().second.cooling_time;
    };
    // From the cycle the nominal solve predicts (each place's share of the span rescaled with
    // the film, follow_cycle): often within 1 % at once, two solves where five were.
    std::vector<double> predicted = r.at_samples;
    const double start = follow_cycle(predicted, spec, samples.size(), samples.thickness);
    int solves = 0;
    const double cooling = consistent_cooling(need, start, 0.01, kCycleIterations, &solves,
                                              std::pair(solved.front().first, r.cooling_time));
    for (const auto& [c, s] : solved)
      if (c == cooling) r = s;
    r.cycle_iterations = int(solved.size());
  }
  summarize_faces(scene, r, asked.size(), samples, across);
  r.circuits = coolant_circuits(layout, scene.spec(), r.bore_heat);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

std::string not_in_steel(const mold::Scene& scene, const mold::Layout& layout, const Vec3& p) {
  const geometry::Box& block = scene.block_bounds();
  if (!block.contains(p)) return "outside the block (" + describe(block) + ")";
  if (const auto& cavity = scene.spec().cavity; cavity && cavity->box && !cavity->is_patch()) {
    // Strictly inside: the cavity's surface is the steel's boundary, where the samples lie.
    const geometry::Box& part = *cavity->box;
    const double tolerance = 1e-6 * (1 + part.size().norm());
    if (((p.array() > part.min.array() + tolerance) && (p.array() < part.max.array() - tolerance)).all())
      return "inside the cavity (the part, " + describe(part) + ")";
  }
  for (const mold::Bore& b : layout.bores)
    if (geometry::point_segment_distance(p, {b.hole.p0, b.hole.p1}) < b.hole.radius)
      return "inside bore " + b.name() + " (the coolant)";
  return "";
}

std::vector<Vec3> read_steel_points(const std::string& path, const mold::Scene& scene, const mold::Layout& layout) {
  std::vector<int> lines;
  const std::vector<Vec3> points = io::read_points_csv(path, &lines);
  for (std::size_t i = 0; i < points.size(); ++i)
    if (const std::string why = not_in_steel(scene, layout, points[i]); !why.empty()) {
      std::ostringstream at;
      at << "point (" << points[i].x() << ", " << points[i].y() << ", " << points[i].z() << ") lies " << why
         << ": the model gives temperatures in the steel only";
      throw io::InputError(path, lines[i], 1, "x,y,z", at.str());
    }
  return points;
}

}  // namespace mtcs::eval
