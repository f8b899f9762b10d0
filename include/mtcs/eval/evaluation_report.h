#pragma once
// One layout's evaluation as `mtcs evaluate` prints it: text for people (objectives, each violated
// constraint with what was found against what its rule needs, in units; the stages' times) or
// one JSON object {feasible, objectives, violation, violations[{kind, elements, distance, margin,
// where}], stages[{name, seconds}]}.

#include <ostream>

#include "mtcs/eval/evaluation.h"
#include "mtcs/eval/pipeline.h"
#include "mtcs/mold/layout.h"

namespace mtcs::eval {

void write_evaluation_json(std::ostream& out, const Evaluation& e, const Pipeline& pipeline);
void write_evaluation_text(std::ostream& out, const Evaluation& e, const Pipeline& pipeline, const mold::Layout& layout);

}  // namespace mtcs::eval
