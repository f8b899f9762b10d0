// The pipeline already measures each bore against the part, the keep-outs and the other bores
// with the exact solid-cylinder kernels (the clearance as upper bound) and places each
// violation; this report keeps those checks and tells crossing from mere closeness.

#include "mtcs/run/layout_interference.h"

#include <iomanip>
#include <limits>
#include <nlohmann/json.hpp>

#include "mtcs/mold/decoder.h"

namespace mtcs::run {

LayoutInterference layout_interference(const eval::Pipeline& pipeline, const mold::Genome& genome) {
  const mold::Scene& scene = pipeline.scene();
  const mold::Layout layout = mold::decode(scene, genome);
  const eval::Evaluation e = pipeline.constraints(layout);
  LayoutInterference r;
  r.bores = layout.bores.size();
  r.nearest = std::numeric_limits<double>::infinity();
  for (const auto& v : e.violations)
    if (v.kind == eval::ViolationKind::BoreCavity || v.kind == eval::ViolationKind::BoreKeepout ||
        v.kind == eval::ViolationKind::BoreBore) {
      r.found.push_back(v);
      r.crossing += v.distance <= 0;
      r.nearest = std::min(r.nearest, v.distance);
    }
  if (scene.spec().cavity) r.against.push_back("cavity");
  for (const auto& k : scene.spec().keep_outs) r.against.push_back(k.name);
  return r;
}

void write_layout_interference_json(std::ostream& os, const LayoutInterference& r, const std::string& mold_path,
                                    const std::string& layout_path) {
  nlohmann::ordered_json out;
  out["mold"] = mold_path;
  out["layout"] = layout_path;
  out["bores"] = r.bores;
  out["against"] = r.against;
  out["pairs"] = r.crossing;  // bore pairs that touch, cross or lie inside each other
  out["distance"] = r.found.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(r.nearest);
  auto& list = out["violations"] = nlohmann::ordered_json::array();
  for (const auto& v : r.found)
    list.push_back({{"kind", eval::to_string(v.kind)},
                    {"bore", v.elements.at(0)},
                    {"against", v.elements.size() > 1 ? v.elements[1] : ""},
                    {"interferes", v.distance <= 0},
                    {"distance", v.distance},
                    {"clearance", v.margin},
                    {"where", {v.where.x(), v.where.y(), v.where.z()}}});
  os << out.dump(2) << "\n";
}

void write_layout_interference_text(std::ostream& os, const LayoutInterference& r) {
  os << r.bores << " bores against ";
  for (std::size_t i = 0; i < r.against.size(); ++i) os << (i ? ", " : "") << r.against[i];
  os << (r.against.empty() ? "each other" : " and each other") << ": " << r.crossing << " interfering, "
     << r.found.size() - std::size_t(r.crossing) << " closer than their clearance\n";
  if (r.found.empty()) return;
  os << "\n" << std::left << std::setw(13) << "kind" << std::setw(10) << "bore" << std::setw(18) << "against"
     << std::right << std::setw(12) << "distance" << std::setw(11) << "clearance" << "  where\n";
  for (const auto& v : r.found) {
    os << std::left << std::setw(13) << eval::to_string(v.kind) << std::setw(10) << v.elements.at(0) << std::setw(18)
       << (v.elements.size() > 1 ? v.elements[1] : "") << std::right << std::fixed << std::setprecision(4)
       << std::setw(12) << v.distance << std::setw(11) << v.margin << "  (" << std::setprecision(3)
       << v.where.x() << ", " << v.where.y() << ", " << v.where.z() << ")"
       << (v.distance <= 0 ? "  INTERFERES" : "") << "\n";
    os.unsetf(std::ios::fixed);
  }
}

}  // namespace mtcs::run
