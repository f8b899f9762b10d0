#pragma once
// The conduction problem of one layout as plain JSON, for a solver outside mtcs (FreeFem++, a
// commercial tool) to solve the same physics: the block, its faces' films, the cavity's
// triangles with their condition, the bores' flowed parts with their films (and, where the
// coolant warms along a circuit, each one's circuit, position and capacity_W_K = rho Q c_p), the
// samples.
// Units in the file: mm, degrees C, W/(m K), W/(m^2 K), W/m^2 (the spec's SI, lengths in mm);
// "film": null is the Dirichlet limit (an infinite film). Written by `mtcs thermal --problem`;
// read by experiments/thermal/freefem_coupled.

#include <ostream>
#include <string>

#include "mtcs/mold/layout.h"
#include "mtcs/mold/scene.h"
#include "mtcs/thermal/model.h"

namespace mtcs::eval {

void write_thermal_problem_json(std::ostream& out, const thermal::Model& model, const thermal::Samples& samples);
// The scene's problem for the layout (its setting, channels and samples) to `path`, whole or not at all.
void write_thermal_problem_file(const std::string& path, const mold::Scene& scene, const mold::Layout& layout);

}  // namespace mtcs::eval
