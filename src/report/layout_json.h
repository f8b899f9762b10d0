#pragma once
// One layout as the page draws and lists it: its bores (hole, flow stretch, circuit, entry,
// plug), each circuit's inlet and outlet, and the violated constraints with the closest points.

#include "mtcs/eval/evaluation.h"
#include "mtcs/mold/layout.h"
#include "scene_json.h"

namespace mtcs::report {

Json layout_json(const mold::Layout& layout);
Json violations_json(const std::vector<eval::Violation>& violations);

}  // namespace mtcs::report
