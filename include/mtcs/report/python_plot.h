#pragma once
// PNG plots through the repo's matplotlib scripts (scripts/*.py), as the experiments render
// theirs: run with /usr/bin/python3 when it has matplotlib; otherwise the user is told the
// command that renders them later.

#include <ostream>
#include <string>
#include <vector>

namespace mtcs::report {

// Runs scripts/SCRIPT with the arguments (its output goes to stderr). Returns true when it ran
// and succeeded; otherwise writes to `log` why not and the command to run by hand.
bool render_plot(const std::string& script, const std::vector<std::string>& args, std::ostream& log);
// The command that renders it by hand.
std::string plot_command(const std::string& script, const std::vector<std::string>& args);

}  // namespace mtcs::report
