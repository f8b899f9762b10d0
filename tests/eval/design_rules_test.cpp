// The design rules per bore (issue 42 item 6) against distances read off the drawing: bores
// placed at known heights under a box cavity (the plate), a patch (the reference block) and a mesh
// part (the cup's floor), the pitch between parallel legs, junction partners left out.

#include <catch2/catch.hpp>
#include <cmath>
#include <nlohmann/json.hpp>

#include "mtcs/eval/design_rules.h"
#include "mtcs/mold/mold_spec.h"
#include "support/bundled_variant.h"
#include "support/paths.h"

using namespace mtcs;
using geometry::Vec3;

namespace {

mold::Bore bore(const Vec3& a, const Vec3& b, double diameter, int circuit, int segment) {
  mold::Bore r{};
  r.flow_start = r.hole.p0 = a, r.flow_end = r.hole.p1 = b;
  r.hole.radius = diameter / 2;
  r.diameter = diameter, r.circuit = circuit, r.segment = segment;
  r.drilled_length = (b - a).norm();
  return r;
}

}  // namespace

TEST_CASE("design rules: depth under a box cavity and pitch between parallel legs, as drawn", "[eval][design]") {
  // The plate's cavity: x 50..250, y 25..175, z 105..108. A U of 8 mm bores 16 mm under it
  // (axis at z = 89: 2 D), its legs 40 mm apart (5 D), joined by a cross bore.
  const mold::Scene scene(mold::load_mold_spec(MTCS_SOURCE_DIR + "/molds/plate.yaml"));
  mold::Layout layout;
  layout.bores = {bore({0, 60, 89}, {150, 60, 89}, 8, 0, 0), bore({150, 60, 89}, {150, 100, 89}, 8, 0, 1),
                  bore({150, 100, 89}, {0, 100, 89}, 8, 0, 2), bore({0, 160, 60}, {300, 160, 60}, 10, 1, 0)};
  layout.junctions = {{0, 1}, {1, 2}};
  const eval::DesignRules rules = eval::design_rules(scene, layout);
  REQUIRE(rules.bores.size() == 4);
  CHECK(rules.bores[0].depth_d() == Approx(2.0).epsilon(1e-12));
  CHECK(rules.bores[2].depth_d() == Approx(2.0).epsilon(1e-12));
  CHECK(rules.bores[0].pitch_d() == Approx(5.0).epsilon(1e-12));  // to the other leg: the cross bore is joined
  CHECK(rules.bores[0].pitch_to == "c0.b2");
  // The cross bore's nearest unjoined bore: none of its circuit; c1.b0 at y 160, z 60.
  CHECK(rules.bores[1].pitch_to == "c1.b0");
  CHECK(rules.bores[1].pitch == Approx(std::hypot(160 - 100, 89 - 60)).epsilon(1e-12));
  // 10 mm bore 45 mm under the cavity: depth 4.5 D, far; drilled 300 mm: 30 D.
  CHECK(rules.bores[3].depth_d() == Approx(4.5).epsilon(1e-12));
  CHECK(eval::DesignRules::verdict(rules.bores[3].depth_d(), eval::kDepthRange) == "far");
  CHECK(eval::DesignRules::verdict(1.2, eval::kDepthRange) == "near");
  CHECK(eval::DesignRules::verdict(2.0, eval::kPitchRange) == "near");
  CHECK(eval::DesignRules::verdict(4.0, eval::kPitchRange).empty());
  CHECK(rules.bores[3].drilled_ratio == Approx(30));
  const auto j = nlohmann::json::parse(eval::design_rules_json_text(rules));
  CHECK(j["bores"][3]["depth_verdict"] == "far");
  CHECK(j["bores"][0]["pitch_to"] == "c0.b2");
  CHECK_THAT(eval::design_rules_text(rules), Catch::Contains("c1.b0") && Catch::Contains("4.50 far"));
}

TEST_CASE("design rules: depth under a patch and under a mesh part's floor", "[eval][design]") {
  // The reference block's patch: z = 60 over x 30..90, y 16..64. Axis at z = 44, 8 mm: 2 D.
  const mold::Scene block(mold::load_mold_spec(MTCS_SOURCE_DIR + "/molds/thermal_block.yaml"));
  mold::Layout one;
  one.bores = {bore({0, 40, 44}, {120, 40, 44}, 8, 0, 0)};
  const eval::DesignRules under_patch = eval::design_rules(block, one);
  CHECK(under_patch.bores[0].depth_d() == Approx(2.0).epsilon(1e-12));
  CHECK(std::isinf(under_patch.bores[0].pitch));  // no other bore
  // The cup's floor (a mesh): outer bottom at z = 40 over x 50..170, y 50..130. Axis at z = 28.
  const mold::Scene cup(mold::load_mold_spec(mtcs_test::bundled_variant("cup", {})));
  mold::Layout floor;
  floor.bores = {bore({110, 0, 28}, {110, 180, 28}, 8, 0, 0)};
  CHECK(eval::design_rules(cup, floor).bores[0].depth_d() == Approx(1.5).epsilon(1e-9));
}
