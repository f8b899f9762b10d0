// Issue 16, item 4: SMS-EMOA's live line shows the front's hypervolume and size (its scalar
// "best" was one member of the front and could get worse as the front grew).

#include <catch2/catch.hpp>
#include <cstdio>

#include "mtcs/opt/sms_emoa.h"
#include "mtcs/run/progress_line.h"
#include "mtcs/run/session.h"
#include "support/paths.h"

using namespace mtcs;

TEST_CASE("issue 16: SMS-EMOA's progress line gives the hypervolume in scaled objectives and the front size",
          "[run][issue16]") {
  run::RunOverrides o;
  o.algorithm = "sms-emoa";
  o.seed = 5;
  o.evaluations = 200;
  o.ref = {40, 40, 40};
  const run::Session session(MTCS_SOURCE_DIR + "/molds/plate_wall_distance.yaml", o);
  const run::MoldOptimizer optimizer(session.problem(), session.scene(), session.config());
  const opt::Generation g = optimizer.run(nullptr, {});
  const auto front = opt::SmsEmoa::front(g);
  REQUIRE_FALSE(front.empty());
  // The reference: raw hypervolume over the product of the mold's scales, against the given
  // reference point of 40 per scaled objective.
  double scales = 1;
  std::vector<double> raw_ref;
  for (const auto obj : session.spec().objectives.use) {
    scales *= session.spec().objectives.scale(obj);
    raw_ref.push_back(40 * session.spec().objectives.scale(obj));
  }
  CHECK(optimizer.scaled_reference() == std::vector<double>{40, 40, 40});
  const double hv = opt::hypervolume(front, raw_ref) / scales;
  REQUIRE(hv > 0);
  CHECK(optimizer.scaled_hypervolume(front) == Approx(hv).epsilon(1e-12));
  char expected[80];
  std::snprintf(expected, sizeof expected, "HV %.6g | front %zu |", hv, front.size());
  const std::string line = run::progress_line(optimizer, g, 1.0, g.evaluations);
  CHECK_THAT(line, Catch::Contains(expected));
  CHECK_THAT(line, !Catch::Contains("best"));
  CHECK_THAT(run::hypervolume_basis(optimizer, session.objective_names()),
             Catch::Contains("uniformity / 5, worst_covered / 20, cost / 1000), reference point [40, 40, 40]: given"));
}
