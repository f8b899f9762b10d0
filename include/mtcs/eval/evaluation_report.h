#pragma once
// One layout's evaluation as `mtcs evaluate` prints it: text for people (objectives, each violated
// constraint with what was found against what its rule needs, in units; the stages' times) or
// one JSON object {feasible, objectives, scalarised, violation, violations[{kind, elements,
// distance, margin, where}], stages[{name, seconds}]}. `scalarised` is scalar_fitness with weights
// 1: the objective `mtcs optimize` prints for its best under the default run config.

#include <ostream>
#include <string>

#include "mtcs/eval/evaluation.h"
#include "mtcs/eval/pipeline.h"
#include "mtcs/mold/layout.h"
#include "mtcs/mold/layout_io.h"

namespace mtcs::eval {

// One violation in words, as the text lists it: "coolant_rise c2: coolant rise 3.41 K, at most
// 3.00 K (thermal.coolant.max_rise)" (without the place).
std::string violation_text(const Violation& v);

// `changes`: what reading the layout changed (mold::read_layout), listed first in the text and as
// "changes" [{circuit, waypoint, what}] in the JSON.
void write_evaluation_json(std::ostream& out, const Evaluation& e, const Pipeline& pipeline, const mold::MoldSpec& spec,
                           const mold::Layout& layout, const std::vector<mold::LayoutChange>& changes = {});
void write_evaluation_text(std::ostream& out, const Evaluation& e, const Pipeline& pipeline, const mold::MoldSpec& spec,
                           const mold::Layout& layout, const std::vector<mold::LayoutChange>& changes = {});

}  // namespace mtcs::eval
