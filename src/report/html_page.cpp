#include "mtcs/report/html_page.h"

#include <map>
#include <stdexcept>

#include "assets.h"
#include "base64.h"

namespace mtcs::report {
namespace {

// The template with each {{NAME}} replaced by its value, in one pass over the template only
// (a value that contains "{{...}}", such as a mold's text in the data, stays as it is).
std::string fill(const std::string& page, const std::map<std::string, std::string>& values) {
  std::string out;
  std::size_t done = 0, used = 0;
  for (std::size_t at = page.find("{{"); at != std::string::npos; at = page.find("{{", done)) {
    const std::size_t end = page.find("}}", at);
    const auto value = end == std::string::npos ? values.end() : values.find(page.substr(at + 2, end - at - 2));
    if (value == values.end()) throw std::logic_error("report.html: unknown placeholder at " + std::to_string(at));
    out.append(page, done, at - done).append(value->second);
    done = end + 2;
    ++used;
  }
  if (used != values.size()) throw std::logic_error("report.html: a placeholder is missing or repeated");
  return out.append(page, done);
}

std::string replace_all(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

std::string escape_html(const std::string& s) {
  std::string out;
  for (const char c : s) {
    if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '&') out += "&amp;";
    else if (c == '"') out += "&quot;";
    else out += c;
  }
  return out;
}

std::string data_module(const std::string& code) { return "data:text/javascript;base64," + base64(code.data(), code.size()); }

// three.module.min.js imports its core by a relative path, which a data: module cannot resolve:
// the core gets the bare name "three/core" in the import map instead (the files stay as npm
// ships them; scripts/vendor_three.sh).
std::string import_map() {
  const std::string module = replace_all(assets::text("three/three.module.min.js"), "\"./three.core.min.js\"", "\"three/core\"");
  return "{\"imports\": {\"three\": \"" + data_module(module) + "\",\n\"three/core\": \"" +
         data_module(assets::text("three/three.core.min.js")) + "\",\n\"three/addons/controls/OrbitControls.js\": \"" +
         data_module(assets::text("three/OrbitControls.js")) + "\",\n\"mtcs/page\": \"" +
         data_module(assets::text("page.js")) + "\"}}";
}

}  // namespace

std::string html_page(const std::string& title, const std::string& data_json, const std::string& page) {
  return fill(assets::text(page + ".html"),
              {{"TITLE", escape_html(title)},
               {"THREE_LICENSE", replace_all(assets::text("three/LICENSE"), "--", "- -")},  // inside an HTML comment
               {"STYLE", assets::text("report.css")},
               {"IMPORT_MAP", import_map()},
               // "</" inside the JSON would end its script element; "<\/" is the same string in JSON.
               {"DATA", replace_all(data_json, "</", "<\\/")},
               {"SCRIPT", assets::text(page + ".js")}});
}

}  // namespace mtcs::report
