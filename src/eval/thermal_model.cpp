#include "mtcs/eval/thermal_model.h"

#include <algorithm>
#include <stdexcept>

#include "mtcs/eval/circuit_hydraulics.h"
#include "mtcs/eval/coolant.h"
#include "mtcs/eval/cycle_time.h"
#include "mtcs/eval/part_coupling.h"
#include "mtcs/eval/wall_passage.h"
#include "surface_samples.h"

namespace mtcs::eval {

using geometry::Box;
using geometry::Vec3;

namespace {

thermal::BlockFace block_face(mold::Face f) {
  switch (f) {
    case mold::Face::NegX: return thermal::BlockFace::NegX;
    case mold::Face::PosX: return thermal::BlockFace::PosX;
    case mold::Face::NegY: return thermal::BlockFace::NegY;
    case mold::Face::PosY: return thermal::BlockFace::PosY;
    case mold::Face::NegZ: return thermal::BlockFace::NegZ;
    case mold::Face::PosZ: return thermal::BlockFace::PosZ;
  }
  return thermal::BlockFace::PosZ;
}

// The last region holding p, or none.
const mold::HeatRegion* region_at(const Vec3& p, const std::vector<mold::HeatRegion>& regions) {
  const mold::HeatRegion* found = nullptr;
  for (const mold::HeatRegion& r : regions)
    if (r.box.contains(p)) found = &r;
  return found;
}

// The cavity's condition per point: a region's fixed flux where one holds the point; elsewhere
// the spec's condition (the flux model's flux, or the part's coupling).
// With the part's local wall thickness (cavity.wall_thickness: local), the film per triangle
// at its own thickness, in the nominal cycle (the thickest wall's).
class CavityCondition {
 public:
  explicit CavityCondition(const mold::MoldSpec& spec) : spec_(spec), regions_(spec.thermal.regions) {
    if (spec.thermal.cavity_condition == mold::CavityCondition::Coupled) {
      const PartCoupling c = cavity_coupling(spec);
      film_ = c.film, part_ = c.temperature;
      times_ = nominal_cycle(spec);
    } else {
      flux_ = cavity_heat_flux(spec);
    }
  }
  thermal::HeatedTriangle at(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& where, double thickness = 0) const {
    if (const mold::HeatRegion* r = region_at(where, regions_)) return {a, b, c, r->flux};
    if (thickness > 0 && film_ > 0 && !spec_.thermal.part_film)
      return {a, b, c, flux_, part_coupling(spec_.thermal.polymer, thickness, times_.in_mold, times_.cycle).film, part_};
    return {a, b, c, flux_, film_, part_};
  }

 private:
  const mold::MoldSpec& spec_;
  const std::vector<mold::HeatRegion>& regions_;
  double flux_ = 0, film_ = 0, part_ = 0;
  CycleTimes times_;
};

// A flat rectangle (zero extent along one axis) as triangles facing `melt`, cut wherever a
// region's bound crosses it, each piece with its own flux.
void add_rectangle(const Box& rect, const Vec3& melt, const CavityCondition& condition,
                   const std::vector<mold::HeatRegion>& regions, std::vector<thermal::HeatedTriangle>& out) {
  const auto [i, j, k] = patch_axes(rect);
  auto cuts = [&, &rect = rect](int a) {
    std::vector<double> c{rect.min[a], rect.max[a]};
    for (const mold::HeatRegion& r : regions)
      for (const double x : {r.box.min[a], r.box.max[a]})
        if (x > rect.min[a] && x < rect.max[a]) c.push_back(x);
    std::sort(c.begin(), c.end());
    c.erase(std::unique(c.begin(), c.end()), c.end());
    return c;
  };
  const std::vector<double> ci = cuts(i), cj = cuts(j);
  for (std::size_t b = 0; b + 1 < cj.size(); ++b) {
    for (std::size_t a = 0; a + 1 < ci.size(); ++a) {
      auto corner = [&, i = i, j = j](std::size_t u, std::size_t v) {
        Vec3 p = rect.min;
        p[i] = ci[a + u], p[j] = cj[b + v];
        return p;
      };
      const Vec3 p00 = corner(0, 0), p10 = corner(1, 0), p11 = corner(1, 1), p01 = corner(0, 1);
      const Vec3 mid = (p00 + p11) / 2;
      if ((p10 - p00).cross(p01 - p00).dot(melt) > 0) {
        out.push_back(condition.at(p00, p10, p11, mid));
        out.push_back(condition.at(p00, p11, p01, mid));
      } else {
        out.push_back(condition.at(p00, p11, p10, mid));
        out.push_back(condition.at(p00, p01, p11, mid));
      }
    }
  }
}

}  // namespace

double cavity_heat_flux(const mold::MoldSpec& spec) {
  return spec.thermal.heat_flux ? *spec.thermal.heat_flux : default_heat_flux(spec);
}

thermal::Setting thermal_setting(const mold::Scene& scene) { return thermal_setting(scene, scene.spec()); }

thermal::Setting thermal_setting(const mold::Scene& scene, const mold::MoldSpec& spec) {
  if (!spec.cavity) throw std::invalid_argument("the thermal model needs a cavity");
  const mold::ThermalSpec& t = spec.thermal;
  thermal::Setting s;
  s.block = scene.block_bounds();
  s.conductivity = t.conductivity;
  for (auto& f : s.faces) f = {t.ambient_film, t.ambient_temperature};
  for (const mold::Face f : t.adiabatic_faces) s.faces[std::size_t(block_face(f))].film = 0;

  const mold::Cavity& cavity = *spec.cavity;
  const CavityCondition condition(spec);
  if (cavity.is_patch()) {
    // The melt lies outside the block, beyond the patch's face.
    add_rectangle(*cavity.box, mold::normal_of(*cavity.patch_face), condition, t.regions, s.heat_in);
  } else if (cavity.box) {
    s.cavity_box = *cavity.box;
    const Box& b = *cavity.box;
    for (int k = 0; k < 3; ++k) {
      for (const bool upper : {false, true}) {
        Box face = b;
        (upper ? face.min : face.max)[k] = upper ? b.max[k] : b.min[k];
        Vec3 inward = Vec3::Zero();
        inward[k] = upper ? -1 : 1;  // the melt is inside the box
        add_rectangle(face, inward, condition, t.regions, s.heat_in);
      }
    }
  } else {
    const mesh::TriangleMesh& m = cavity.mesh->mesh;
    s.cavity_mesh = std::make_shared<const mesh::TriangleMesh>(m);
    const std::vector<double>& thickness = scene.cavity_thickness();
    for (std::size_t i = 0; i < m.triangles.size(); ++i) {
      const Vec3 a = m.corner(i, 0), b = m.corner(i, 1), c = m.corner(i, 2);
      // Outward-oriented mesh: reversed, the triangle faces the melt inside the part.
      s.heat_in.push_back(condition.at(a, c, b, (a + b + c) / 3, thickness.empty() ? 0 : thickness[i]));
    }
  }
  return s;
}

std::vector<thermal::Channel> thermal_channels(const mold::Layout& layout, const mold::MoldSpec& spec) {
  return thermal_channels(layout, spec, bore_flows(layout, spec));
}

std::vector<thermal::Channel> thermal_channels(const mold::Layout& layout, const mold::MoldSpec& spec,
                                               std::span<const double> bore_flow) {
  const mold::ThermalSpec& t = spec.thermal;
  // Driven by a supply pressure alone, each circuit takes the flow its resistance lets through.
  const auto flow_of = [&](std::size_t i) { return i < bore_flow.size() ? bore_flow[i] : 0.0; };
  const WaterProperties water = water_properties(t.coolant_temperature);
  std::vector<thermal::Channel> channels;
  for (std::size_t i = 0; i < layout.bores.size(); ++i) {
    const mold::Bore& b = layout.bores[i];
    thermal::Channel c;
    c.axis = {b.flow_start, b.flow_end};
    c.radius = b.diameter / 2;
    c.coolant = t.coolant_temperature;
    if (t.coolant_film) c.film = *t.coolant_film;
    else if (flow_of(i) > 0) c.film = wall_film(b, flow_of(i), t.coolant_temperature);
    if (t.coolant_rise && flow_of(i) > 0) {
      c.circuit = b.circuit;
      c.position = b.segment;
      c.capacity = capacity_rate(flow_of(i), water);
    }
    channels.push_back(c);
  }
  return channels;
}

double cavity_flux_at(const mold::MoldSpec& spec, const Vec3& p) {
  if (const mold::HeatRegion* r = region_at(p, spec.thermal.regions)) return r->flux;
  return spec.thermal.cavity_condition == mold::CavityCondition::Coupled ? 0.0 : cavity_heat_flux(spec);
}

bool cavity_heated_at(const mold::MoldSpec& spec, const Vec3& p) {
  if (const mold::HeatRegion* r = region_at(p, spec.thermal.regions)) return r->flux > 0;
  return spec.thermal.cavity_condition == mold::CavityCondition::Coupled || cavity_heat_flux(spec) > 0;
}

thermal::Samples thermal_samples(const mold::Scene& scene) {
  const mold::MoldSpec& spec = scene.spec();
  if (!spec.cavity) throw std::invalid_argument("the thermal samples need a cavity");
  const mold::Cavity& cavity = *spec.cavity;
  const SurfaceSamples s = sample_cavity(cavity, spec.thermal.sample_spacing.value_or(cavity.sample_spacing));
  thermal::Samples all, heated;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const Vec3 p(s.x[i], s.y[i], s.z[i]);
    const double wall = cavity.local_thickness ? scene.wall_thickness_at(p, s.normal[i]) : 0;
    for (thermal::Samples* into : {&all, &heated}) {
      if (into == &heated && !cavity_heated_at(spec, p)) continue;
      into->points.push_back(p), into->weights.push_back(s.weight[i]), into->normals.push_back(s.normal[i]);
      if (cavity.local_thickness) into->thickness.push_back(wall);
    }
  }
  const bool use_heated = spec.thermal.objective_surface == mold::ObjectiveSurface::Heated && heated.size() > 0;
  return use_heated ? heated : all;
}

}  // namespace mtcs::eval
