#include "layout_json.h"

#include <map>

#include "mtcs/eval/circuit_hydraulics.h"

namespace mtcs::report {

Json layout_json(const mold::Layout& layout) {
  Json bores = Json::array();
  // Per circuit, its first and last flow segment: the coolant enters at the first's flow start
  // and leaves at the last's flow end.
  std::map<int, std::pair<const mold::Bore*, const mold::Bore*>> ends;
  for (const mold::Bore& b : layout.bores) {
    bores.push_back({{"name", b.name()},
                     {"circuit", b.circuit},
                     {"segment", b.segment},
                     {"p0", vec_json(b.hole.p0)},
                     {"p1", vec_json(b.hole.p1)},
                     {"diameter", b.diameter},
                     {"flow", {vec_json(b.flow_start), vec_json(b.flow_end)}},
                     {"length", b.drilled_length},
                     {"entry_face", mold::to_string(b.entry_face)},
                     {"entry_angle", b.entry_angle_deg},
                     {"plugged", b.plugged},
                     {"through", b.through},
                     {"dead_end", b.dead_end}});
    if (is_blind(b.kind)) {
      bores.back()["insert"] = mold::to_string(b.kind);
      if (b.tube_outer > 0) bores.back()["tube"] = {b.tube_outer, b.tube_inner};
    }
    auto [it, fresh] = ends.try_emplace(b.circuit, &b, &b);
    if (b.segment < it->second.first->segment) it->second.first = &b;
    if (b.segment > it->second.second->segment) it->second.second = &b;
  }
  Json ports = Json::array();
  for (const auto& [circuit, e] : ends)
    ports.push_back({{"circuit", circuit},
                     {"inlet", vec_json(e.first->flow_start)},
                     // A blind bore's coolant comes back out at its entry.
                     {"outlet", vec_json(is_blind(e.second->kind) ? e.second->flow_start : e.second->flow_end)}});
  return {{"bores", std::move(bores)}, {"ports", std::move(ports)}, {"circuits", ends.size()}, {"plugs", layout.plugs}};
}

Json coolant_json(const mold::Layout& layout, const mold::MoldSpec& spec, const std::vector<double>& bore_heat) {
  const eval::CoolantCircuits cc = eval::coolant_circuits(layout, spec, bore_heat);
  if (!cc.flowing) return nullptr;
  Json j = Json::parse(eval::coolant_circuits_json_text(cc));
  j["bores"] = Json::array();
  const std::vector<eval::BoreCoolant> at = eval::bore_coolant(layout, spec, bore_heat);
  for (std::size_t i = 0; i < at.size(); ++i)
    j["bores"].push_back({{"name", layout.bores[i].name()}, {"in", at[i].in}, {"out", at[i].out}});
  return j;
}

Json violations_json(const std::vector<eval::Violation>& violations) {
  Json out = Json::array();
  for (const auto& v : violations) {
    Json j{{"kind", eval::to_string(v.kind)}, {"elements", v.elements}, {"distance", v.distance}, {"margin", v.margin},
           {"amount", v.amount}, {"where", vec_json(v.where)}};
    if (v.closest) j["closest"] = {vec_json(v.closest->first), vec_json(v.closest->second)};
    out.push_back(std::move(j));
  }
  return out;
}

}  // namespace mtcs::report
