// STEP without OpenCASCADE: export_bores refuses --format step before this is reached.
#include "mtcs/io/input_error.h"
#include "mtcs/report/layout_export.h"
#include "step_writer.h"

namespace mtcs::report {

bool step_available() { return false; }

void write_step(const std::string&, const mold::Layout&) { throw io::InputError("", 0, 0, "--format", kStepMissing); }

}  // namespace mtcs::report
