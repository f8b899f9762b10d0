// The part's other face straight across its wall (eval::across_part), and the core/cavity
// difference mtcs thermal reports from it.
#include <catch2/catch.hpp>

#include <cmath>

#include "mtcs/eval/across_part.h"
#include "mtcs/eval/cavity_temperature.h"
#include "mtcs/eval/thermal_model.h"
#include "mtcs/mold/decoder.h"
#include "mtcs/run/session.h"
#include "support/paths.h"

using namespace mtcs;
using geometry::Vec3;

TEST_CASE("across the part: a plate's faces pair 3 mm apart, its thin edges' samples do not", "[eval][thermal]") {
  const run::Session session(MTCS_SOURCE_DIR + "/molds/plate.yaml", run::RunOverrides{});
  thermal::Samples all = eval::thermal_samples(session.scene());
  const auto across = eval::across_part(session.scene(), all, 9);
  std::size_t paired = 0;
  for (std::size_t i = 0; i < all.size(); ++i) {
    const Vec3& n = all.normals[i];
    REQUIRE(std::abs(n.norm() - 1) < 1e-12);
    if (std::abs(n.z()) == 1) {  // the plate's bottom face (the heated one): its top 3 mm above
      REQUIRE(across[i]);
      CHECK((*across[i] - all.points[i]).norm() == Approx(3));
      CHECK(across[i]->z() == Approx(all.points[i].z() - 3 * n.z()));
      ++paired;
    } else {
      CHECK_FALSE(across[i]);  // 150 or 200 mm across
    }
  }
  CHECK(paired > 0);
}

TEST_CASE("across the part: a cup's walls pair with their other face, its rim with nothing", "[eval][thermal]") {
  const run::Session session(MTCS_SOURCE_DIR + "/molds/cup.yaml", run::RunOverrides{});
  const thermal::Samples samples = eval::thermal_samples(session.scene());
  const auto across = eval::across_part(session.scene(), samples, 7.5);
  const mesh::TriangleBvh& bvh = *session.scene().cavity_bvh();
  std::size_t paired = 0, rim = 0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    if (!across[i]) {
      rim += samples.normals[i].z() > 0.9;  // the rim's top: the ray runs 40 mm down the wall
      continue;
    }
    ++paired;
    CHECK((*across[i] - samples.points[i]).norm() == Approx(2.5).margin(1e-6));  // the cup's wall
    CHECK(bvh.segment_distance(*across[i], *across[i], 1) < 1e-6);                // on the surface
  }
  CHECK(paired > samples.size() / 2);
  CHECK(rim > 0);
}

TEST_CASE("across the part: the difference mtcs thermal reports is that of the two faces' temperatures", "[eval][thermal]") {
  const run::Session session(MTCS_SOURCE_DIR + "/molds/plate.yaml", run::RunOverrides{});
  const mold::Scene& scene = session.scene();
  const mold::Layout layout = mold::decode(scene, session.read_layout(MTCS_SOURCE_DIR + "/molds/plate.layout.yaml"));
  const eval::CavityTemperature r = eval::cavity_temperature(scene, layout, eval::thermal_query(scene.spec()));
  // The same by hand: the temperatures at the points across, asked for as points.
  const thermal::Samples samples = eval::thermal_samples(scene);
  const auto across = eval::across_part(scene, samples, 3 * scene.spec().cavity->wall_thickness);
  std::vector<Vec3> points;
  for (const auto& q : across)
    if (q) points.push_back(*q);
  const eval::CavityTemperature at = eval::cavity_temperature(scene, layout, eval::thermal_query(scene.spec()), points);
  double sum = 0, area = 0, max = 0;
  for (std::size_t i = 0, k = 0; i < samples.size(); ++i) {
    if (!across[i]) continue;
    const double d = std::abs(at.at_samples[i] - at.at_points[k++]);
    sum += samples.weights[i] * d, area += samples.weights[i], max = std::max(max, d);
  }
  REQUIRE(r.across.pairs == points.size());
  // (float columns over another set of extra points: the same to ~1e-6)
  CHECK(r.across.mean == Approx(sum / area).epsilon(1e-5));
  CHECK(r.across.max == Approx(max).epsilon(1e-5));
  CHECK(r.across.mean > 0);
  CHECK(r.at_points.empty());  // the points across stay inside
}
