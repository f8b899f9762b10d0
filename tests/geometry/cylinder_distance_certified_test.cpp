// The kernel against the certified cases of shared/cases (copied to tests/data): every row's
// [dist_lo, dist_hi] provably contains the true distance.

#include <catch2/catch.hpp>
#include <cmath>
#include <Eigen/Geometry>
#include <random>

#include "mtcs/io/pairs_csv.h"
#include "mtcs/geometry/cylinder_distance.h"
#include "support/paths.h"
#include "support/random_draws.h"

using namespace mtcs::geometry;
using mtcs::io::CylinderPair;

namespace {

const std::vector<CylinderPair>& all_pairs() {
  static const auto pairs = [] {
    auto v = mtcs::io::read_pairs_csv(MTCS_TEST_DATA + "/cylinder_pairs_public.csv");
    const auto exact = mtcs::io::read_pairs_csv(MTCS_TEST_DATA + "/cylinder_pairs_exact.csv");
    v.insert(v.end(), exact.begin(), exact.end());
    return v;
  }();
  return pairs;
}

double allowed(const CylinderPair& p) { return 1e-9 * std::max(1.0, pair_scale(p.a, p.b)); }

double error_to_interval(const CylinderPair& p, double d) {
  return std::max({0.0, *p.dist_lo - d, d - *p.dist_hi});
}

// Rotation about a random axis, and a translation.
struct RigidMotion {
  Eigen::Matrix3d rot;
  Vec3 shift;
  Vec3 operator()(const Vec3& x) const { return rot * x + shift; }
  Cylinder operator()(const Cylinder& c) const { return {(*this)(c.p0), (*this)(c.p1), c.radius}; }
};

}  // namespace

TEST_CASE("certified pairs: error within 1e-9 max(1,S), right verdicts, finite", "[geometry][cylinder][certified]") {
  const auto& pairs = all_pairs();
  REQUIRE(pairs.size() == 43020);
  int failures = 0, wrong_verdicts = 0, non_finite = 0;
  double worst = 0;
  std::string worst_id;
  for (const auto& p : pairs) {
    const auto r = distance(p.a, p.b);
    if (!std::isfinite(r.distance) || !r.witness_a.allFinite() || !r.witness_b.allFinite()) ++non_finite;
    const double e = error_to_interval(p, r.distance);
    if (e > allowed(p)) {
      ++failures;
      if (failures < 10) WARN(p.id << " distance " << r.distance << " interval [" << *p.dist_lo << ", " << *p.dist_hi << "]");
    }
    if (e / allowed(p) > worst) worst = e / allowed(p), worst_id = p.id;
    const bool says_intersecting = r.intersecting();
    if ((says_intersecting && *p.dist_lo > 0) || (!says_intersecting && *p.dist_hi == 0)) {
      ++wrong_verdicts;
      if (wrong_verdicts < 10) WARN("verdict " << p.id << " " << to_string(r.feature) << " d=" << r.distance << " interval [" << *p.dist_lo << ", " << *p.dist_hi << "]");
    }
  }
  INFO("worst error / allowed = " << worst << " at " << worst_id);
  CHECK(failures == 0);
  CHECK(wrong_verdicts == 0);
  CHECK(non_finite == 0);
}

TEST_CASE("certified pairs: witnesses lie on the cylinders and realise the distance", "[geometry][cylinder][certified]") {
  int bad = 0;
  for (const auto& p : all_pairs()) {
    const auto r = distance(p.a, p.b);
    const double tol = 1e-8 * std::max(1.0, pair_scale(p.a, p.b));
    // Witness a inside or on a, b on b: signed distance <= tol (checked with a point cylinder).
    const auto da = distance({r.witness_a, r.witness_a, 0}, p.a, {.exact_verdict = false}).distance;
    const auto db = distance({r.witness_b, r.witness_b, 0}, p.b, {.exact_verdict = false}).distance;
    const double gap = (r.witness_a - r.witness_b).norm();
    if (da > tol || db > tol || std::abs(gap - r.distance) > tol) {
      if (++bad < 5) WARN(p.id << " witness off: " << da << " " << db << " gap " << gap << " d " << r.distance);
    }
  }
  CHECK(bad == 0);
}

TEST_CASE("certified pairs: symmetric and invariant under rigid motions", "[geometry][cylinder][certified]") {
  std::mt19937_64 rng(20261122);
  std::normal_distribution<double> gauss;
  int asymmetric = 0, variant = 0;
  for (const auto& p : all_pairs()) {
    const auto r = distance(p.a, p.b);
    const auto s = distance(p.b, p.a);
    if (std::abs(r.distance - s.distance) > allowed(p) || r.intersecting() != s.intersecting()) ++asymmetric;

    // Motions keep the pair's scale; a pair within 1e-9 S of contact may flip its verdict under
    // the rounding of the moved coordinates, so only the distance is compared.
    const Eigen::Vector3d axis = mtcs_test::draw_vec3(gauss, rng).normalized();
    const RigidMotion m{Eigen::AngleAxisd(gauss(rng), axis).toRotationMatrix(),
                        mtcs_test::draw_vec3(gauss, rng) * 100};
    const auto t = distance(m(p.a), m(p.b));
    const double moved_err = error_to_interval(p, t.distance);
    // Rotating coordinates of size |c| perturbs them by ~1e-16 |c|; allow for it.
    const double slack = 1e-13 * (p.a.p0.norm() + p.b.p0.norm() + 200);
    if (moved_err > allowed(p) + slack) {
      if (++variant < 5) WARN(p.id << " moved " << t.distance << " vs [" << *p.dist_lo << ", " << *p.dist_hi << "]");
    }
  }
  CHECK(asymmetric == 0);
  CHECK(variant == 0);
}

TEST_CASE("certified pairs: the upper-bound contract", "[geometry][cylinder][certified]") {
  for (const double U : {0.5, 5.0, 20.0}) {
    int broken = 0;
    for (const auto& p : all_pairs()) {
      const auto r = distance(p.a, p.b, {.upper_bound = U});
      bool ok;
      if (*p.dist_hi < U && *p.dist_lo < U * (1 - 1e-12)) {
        // Truly below U: the exact distance, unflagged.
        ok = !r.bounded && error_to_interval(p, r.distance) <= allowed(p);
      } else {
        ok = r.bounded ? r.distance >= U : (r.distance >= U * (1 - 1e-12) || error_to_interval(p, r.distance) <= allowed(p));
      }
      if (!ok && ++broken < 5) WARN("U=" << U << " " << p.id << " d=" << r.distance << " bounded=" << r.bounded);
      broken += ok ? 0 : 1;
    }
    INFO("U = " << U);
    CHECK(broken == 0);
  }
}

TEST_CASE("certified pairs: the naive all-sub-distances baseline agrees", "[geometry][cylinder][certified]") {
  int bad = 0;
  for (const auto& p : all_pairs()) {
    if (p.category == "stiff") continue;  // the baseline has no extended-precision verdict
    const auto r = distance_naive(p.a, p.b);
    if (error_to_interval(p, r.distance) > allowed(p)) {
      if (++bad < 5) WARN(p.id << " naive " << r.distance << " vs [" << *p.dist_lo << ", " << *p.dist_hi << "]");
    }
  }
  CHECK(bad == 0);
}
