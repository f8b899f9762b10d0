// The pipeline already measures each bore against the part, the keep-outs and the other bores
// with the exact solid-cylinder kernels (the clearance as upper bound) and places each
// violation; this report keeps those checks and tells crossing from mere closeness.

#include "layout_interference.h"

#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>

#include "mtcs/eval/pipeline.h"
#include "mtcs/mold/decoder.h"
#include "mtcs/mold/layout_io.h"
#include "mtcs/mold/scene.h"

namespace mtcs::cli {

int run_layout_interference(const std::string& mold_path, const std::string& layout_path, bool json) {
  const mold::Scene scene(mold::load_mold_spec(mold_path));
  const mold::Genome genome = mold::load_layout(layout_path, scene.spec());
  const eval::Pipeline pipeline(scene);
  const mold::Layout layout = mold::decode(scene, genome);
  const eval::Evaluation e = pipeline.evaluate(layout);

  std::vector<const eval::Violation*> found;
  for (const auto& v : e.violations)
    if (v.kind == "bore_cavity" || v.kind == "bore_keepout" || v.kind == "bore_bore") found.push_back(&v);
  long crossing = 0;
  double nearest = std::numeric_limits<double>::infinity();
  for (const auto* v : found) {
    crossing += v->distance <= 0;
    nearest = std::min(nearest, v->distance);
  }
  const auto& spec = scene.spec();
  std::vector<std::string> against;
  if (spec.cavity) against.push_back("cavity");
  for (const auto& k : spec.keep_outs) against.push_back(k.name);

  if (json) {
    nlohmann::ordered_json out;
    out["mold"] = mold_path;
    out["layout"] = layout_path;
    out["bores"] = layout.bores.size();
    out["against"] = against;
    out["pairs"] = crossing;  // bore pairs that touch, cross or lie inside each other
    out["distance"] = found.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(nearest);
    auto& list = out["violations"] = nlohmann::ordered_json::array();
    for (const auto* v : found)
      list.push_back({{"kind", v->kind},
                      {"bore", v->elements.at(0)},
                      {"against", v->elements.size() > 1 ? v->elements[1] : ""},
                      {"interferes", v->distance <= 0},
                      {"distance", v->distance},
                      {"clearance", v->margin},
                      {"where", {v->where.x(), v->where.y(), v->where.z()}}});
    std::cout << out.dump(2) << "\n";
    return 0;
  }
  std::cout << layout.bores.size() << " bores against ";
  for (std::size_t i = 0; i < against.size(); ++i) std::cout << (i ? ", " : "") << against[i];
  std::cout << (against.empty() ? "each other" : " and each other") << ": " << crossing << " interfering, "
            << found.size() - std::size_t(crossing) << " closer than their clearance\n";
  if (found.empty()) return 0;
  std::cout << "\n" << std::left << std::setw(13) << "kind" << std::setw(10) << "bore" << std::setw(18) << "against"
            << std::right << std::setw(12) << "distance" << std::setw(11) << "clearance" << "  where\n";
  for (const auto* v : found) {
    std::cout << std::left << std::setw(13) << v->kind << std::setw(10) << v->elements.at(0) << std::setw(18)
              << (v->elements.size() > 1 ? v->elements[1] : "") << std::right << std::fixed << std::setprecision(4)
              << std::setw(12) << v->distance << std::setw(11) << v->margin << "  (" << std::setprecision(3)
              << v->where.x() << ", " << v->where.y() << ", " << v->where.z() << ")"
              << (v->distance <= 0 ? "  INTERFERES" : "") << "\n";
    std::cout.unsetf(std::ios::fixed);
  }
  return 0;
}

}  // namespace mtcs::cli
