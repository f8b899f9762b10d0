#pragma once
// From a scene and a layout to the problem every thermal tier solves (mtcs/thermal/model.h):
// the setting (block, face conditions, heat entering through the cavity surface, the cavity
// void) once per scene, the channels (the flowed part of each bore) per layout, and the cavity
// samples where temperatures are wanted. Units: mm, W, degrees C.

#include <span>
#include <vector>

#include "mtcs/mold/layout.h"
#include "mtcs/mold/scene.h"
#include "mtcs/thermal/model.h"

namespace mtcs::eval {

// The cycle-averaged heat flux (W/mm^2) through the cavity surface outside every region:
// thermal.heat_flux, or default_heat_flux when the spec gives none.
double cavity_heat_flux(const mold::MoldSpec& spec);

// The block (a mesh block by its bounding box), the faces' films (adiabatic ones 0), the heat
// input (thermal.cavity_condition: a fixed flux, or the part's coupling, eval/part_coupling.h;
// a region's flux wins inside it) and the cavity void. The heat input: a box cavity's six faces (a void: heat enters from
// inside it), a patch's rectangle (from outside the block), each split where thermal.regions
// begin and end so every piece has one flux; a mesh cavity's triangles, each with the flux of
// the region holding its centroid. Triangles face the melt. Needs a cavity (else
// std::invalid_argument).
thermal::Setting thermal_setting(const mold::Scene& scene);
// The same with another version of the scene's spec (its thermal section, e.g. another cycle).
thermal::Setting thermal_setting(const mold::Scene& scene, const mold::MoldSpec& spec);

// One channel per bore: its flowed part (flow_start -> flow_end; no plugged dead end, no drill
// point), at the coolant temperature, with the Dirichlet limit, the spec's film, or the film
// of the spec's flow rate through that bore's diameter (Gnielinski).
std::vector<thermal::Channel> thermal_channels(const mold::Layout& layout, const mold::MoldSpec& spec);
// The same with each bore's flow (bore_flows(layout, spec)) already known.
std::vector<thermal::Channel> thermal_channels(const mold::Layout& layout, const mold::MoldSpec& spec,
                                               std::span<const double> bore_flow);

// The fixed heat flux (W/mm^2) into the steel at a point of the cavity surface: that of the
// last region holding the point, else thermal.heat_flux (or the default) under the flux model,
// 0 under the coupled one (its heat follows the wall's temperature).
double cavity_flux_at(const mold::MoldSpec& spec, const geometry::Vec3& p);
// Whether heat enters there: a region's flux > 0, or outside the regions the coupled condition
// or a flux > 0.
bool cavity_heated_at(const mold::MoldSpec& spec, const geometry::Vec3& p);

// The cavity-surface samples with their areas over which the temperature objectives are taken,
// at thermal.sample_spacing (default: the cavity's): those of the tier-0 objectives (every
// sample) when thermal.objective_surface is `all`; with `heated` (the default) only those where
// heat enters (cavity_heated_at), or every one when no sample is heated.
thermal::Samples thermal_samples(const mold::Scene& scene);

}  // namespace mtcs::eval
