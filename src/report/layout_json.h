#pragma once
// One layout as the page draws and lists it: its bores (hole, flow stretch, circuit, entry,
// plug), each circuit's inlet and outlet, and the violated constraints with the closest points.

#include "mtcs/eval/evaluation.h"
#include "mtcs/mold/layout.h"
#include "mtcs/mold/mold_spec.h"
#include "scene_json.h"

namespace mtcs::report {

Json layout_json(const mold::Layout& layout);
Json violations_json(const std::vector<eval::Violation>& violations);
// The layout's coolant circuits (mtcs thermal --json's "coolant": flow, Reynolds number, drop,
// heat, rise per circuit) with each bore's coolant in and out, degrees C ("bores" [{name, in,
// out}], when the heat is known); null without a flow.
Json coolant_json(const mold::Layout& layout, const mold::MoldSpec& spec, const std::vector<double>& bore_heat);

}  // namespace mtcs::report
