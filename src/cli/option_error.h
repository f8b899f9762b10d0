#pragma once
// Errors in what the user typed on the command line, and how main() prints every InputError.
// An option error has no place in a file, so it is shown as "mtcs COMMAND: OPTION: what is
// wrong" (exit 2) rather than with an empty FILE:0:0 prefix.

#include <string>

#include "mtcs/io/input_error.h"

namespace mtcs::cli {

// OPTION as the user would write it: "--out runs/x", "--ref", "MOLD".
inline io::InputError option_error(const std::string& option, const std::string& what) {
  return io::InputError("", 0, 0, option, what);
}

// The message main() prints for an InputError raised while running COMMAND: FILE:LINE:COLUMN
// for a place in a file; without a line, the file or option alone.
inline std::string describe(const io::InputError& e, const std::string& command) {
  const std::string what = e.what();
  if (e.line() > 0) return "mtcs: " + what;
  // InputError's text is "FILE:0:COLUMN: [field 'F': ]WHAT"; keep WHAT.
  const std::string prefix = e.file() + ":" + std::to_string(e.line()) + ":" + std::to_string(e.column()) + ": " +
                             (e.field().empty() ? "" : "field '" + e.field() + "': ");
  const std::string rest = what.rfind(prefix, 0) == 0 ? what.substr(prefix.size()) : what;
  std::string place = e.file().empty() ? e.field() : e.file();
  if (!e.file().empty() && !e.field().empty()) place += ": field '" + e.field() + "'";
  return "mtcs " + command + ": " + (place.empty() ? "" : place + ": ") + rest;
}

}  // namespace mtcs::cli
