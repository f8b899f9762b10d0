#pragma once
// The report page from its data: report.html with its style, its script, the vendored three.js
// (as data: modules behind an import map) and the data (JSON) inlined, so the file opens from
// disk with no network and nothing beside it.

#include <string>

namespace mtcs::report {

// `data_json`: the page's data (run_report.cpp documents the fields report.js reads). `page`: the
// template and script pair, report.html/.js (a run) or interference.html/.js (two components).
std::string html_page(const std::string& title, const std::string& data_json, const std::string& page = "report");

}  // namespace mtcs::report
