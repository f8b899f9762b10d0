#include "mtcs/eval/design_rules.h"

#include <cmath>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <sstream>

#include "mtcs/geometry/segment_distance.h"
#include "cavity_solid.h"

namespace mtcs::eval {

std::string DesignRules::verdict(double in_diameters, DesignRange range) {
  if (!std::isfinite(in_diameters)) return "";
  return in_diameters < range.low ? "near" : in_diameters > range.high ? "far" : "";
}

DesignRules design_rules(const mold::Scene& scene, const mold::Layout& layout) {
  DesignRules out;
  out.max_depth_ratio = scene.spec().drilling.max_depth_ratio;
  const std::optional<CavitySolid> cavity = scene.spec().cavity ? std::optional<CavitySolid>(scene) : std::nullopt;
  const auto joined = [&](std::size_t a, std::size_t b) {
    for (const mold::Junction& j : layout.junctions)
      if ((std::size_t(j.a) == a && std::size_t(j.b) == b) || (std::size_t(j.a) == b && std::size_t(j.b) == a)) return true;
    return false;
  };
  for (std::size_t i = 0; i < layout.bores.size(); ++i) {
    const mold::Bore& b = layout.bores[i];
    BoreRules r;
    r.bore = b.name();
    r.diameter = b.diameter;
    r.drilled_ratio = b.drilled_length / b.diameter;
    if (cavity) {
      const CachedClearance c = cavity->distance(b.hole, std::numeric_limits<double>::infinity());
      if (!c.clear) r.depth = c.distance + b.diameter / 2;  // the steel over it plus the radius (unbounded: exact)
    }
    for (std::size_t k = 0; k < layout.bores.size(); ++k) {
      if (k == i || joined(i, k)) continue;
      const mold::Bore& o = layout.bores[k];
      const double d = geometry::closest_points({b.flow_start, b.flow_end}, {o.flow_start, o.flow_end}).distance;
      if (d < r.pitch) r.pitch = d, r.pitch_to = o.name();
    }
    out.bores.push_back(r);
  }
  return out;
}

std::string design_rules_text(const DesignRules& rules) {
  std::ostringstream s;
  s << "design rules (in bore diameters D; depth: axis to the cavity, " << kDepthRange.low << "-" << kDepthRange.high
    << " D; pitch: axis to the nearest bore not joined to it, " << kPitchRange.low << "-" << kPitchRange.high
    << " D; drilled depth at most " << rules.max_depth_ratio << " D)\n"
    << "  bore      d mm  depth D        pitch D  (to)            drilled D\n";
  const auto value = [&](double v, const std::string& verdict) {
    std::ostringstream c;
    if (std::isfinite(v)) c << std::fixed << std::setprecision(2) << v << (verdict.empty() ? "" : " " + verdict);
    else c << "-";
    return c.str();
  };
  for (const BoreRules& r : rules.bores) {
    const std::string over = r.drilled_ratio > rules.max_depth_ratio ? " over" : "";
    s << "  " << std::left << std::setw(8) << r.bore << std::right << std::fixed << std::setprecision(1) << std::setw(6)
      << r.diameter << "  " << std::left << std::setw(13) << value(r.depth_d(), DesignRules::verdict(r.depth_d(), kDepthRange))
      << "  " << std::setw(10) << value(r.pitch_d(), DesignRules::verdict(r.pitch_d(), kPitchRange)) << std::setw(15)
      << (r.pitch_to.empty() ? "" : "(" + r.pitch_to + ")") << std::right << std::setprecision(1) << std::setw(9)
      << r.drilled_ratio << over << "\n";
  }
  return s.str();
}

std::string design_rules_json_text(const DesignRules& rules) {
  using Json = nlohmann::ordered_json;
  const auto finite = [](double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); };
  Json j{{"depth_range", {kDepthRange.low, kDepthRange.high}},
         {"pitch_range", {kPitchRange.low, kPitchRange.high}},
         {"max_depth_ratio", rules.max_depth_ratio}};
  j["bores"] = Json::array();
  for (const BoreRules& r : rules.bores)
    j["bores"].push_back({{"bore", r.bore},
                          {"diameter", r.diameter},
                          {"depth", finite(r.depth)},
                          {"depth_d", finite(r.depth_d())},
                          {"depth_verdict", DesignRules::verdict(r.depth_d(), kDepthRange)},
                          {"pitch", finite(r.pitch)},
                          {"pitch_d", finite(r.pitch_d())},
                          {"pitch_to", r.pitch_to},
                          {"pitch_verdict", DesignRules::verdict(r.pitch_d(), kPitchRange)},
                          {"drilled_ratio", r.drilled_ratio}});
  return j.dump();
}

}  // namespace mtcs::eval
