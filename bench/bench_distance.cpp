// mtcs bench distance, tolerance and stiff: timings and errors of the cylinder kernel against the
// certified intervals, with FCL measured in the same run as the peer. Each pair is timed over
// `repeat` back-to-back queries (one clock read per batch); medians and 99th percentiles are over
// pairs.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <iostream>
#include <map>
#include <stdexcept>

#include "bench_distance.h"
#include "fcl_peer.h"
#include "mtcs/geometry/cylinder_distance.h"
#include "mtcs/geometry/segment_distance.h"
#include "mtcs/io/pairs_csv.h"

namespace mtcs::bench {

using io::CylinderPair;
using io::read_pairs_csv;
namespace {

using geometry::DistanceRequest;
using geometry::DistanceResult;

struct Sample {
  double ns;
  double err;      // distance from the answer to the certified interval (0 without one)
  double rel_err;  // err / max(1, S)
  const CylinderPair* pair;
};

// Error of a result against the pair's certified interval. A bounded result claims only
// "distance >= U": it is wrong by how far the interval lies below U.
double error_of(const CylinderPair& p, double d, bool bounded, double upper) {
  if (!p.dist_lo || !p.dist_hi) return 0;
  if (bounded) return std::max(0.0, upper * (1 - 1e-12) - *p.dist_hi);
  return std::max({0.0, *p.dist_lo - d, d - *p.dist_hi});
}

template <class F>
Sample time_one(const CylinderPair& p, int repeat, F&& query) {
  volatile double sink = 0;
  const auto t0 = std::chrono::steady_clock::now();
  for (int k = 0; k < repeat; ++k) sink = sink + query();
  const auto t1 = std::chrono::steady_clock::now();
  (void)sink;
  return {std::chrono::duration<double, std::nano>(t1 - t0).count() / repeat, 0, 0, &p};
}

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0;
  const std::size_t k = std::min(v.size() - 1, std::size_t(q * double(v.size() - 1) + 0.5));
  std::nth_element(v.begin(), v.begin() + long(k), v.end());
  return v[k];
}

std::string subtype_of(const std::string& id) {
  const auto dash = id.rfind('-');
  return dash == std::string::npos ? id : id.substr(0, dash);
}

using Variant = std::function<Sample(const CylinderPair&)>;

std::map<std::string, Variant> make_variants(int repeat, double tolerance) {
  std::map<std::string, Variant> v;
  auto kernel = [repeat](DistanceRequest rq) {
    return [repeat, rq](const CylinderPair& p) {
      DistanceResult r;
      Sample s = time_one(p, repeat, [&] { r = geometry::distance(p.a, p.b, rq); return r.distance; });
      s.err = error_of(p, r.distance, r.bounded, rq.upper_bound);
      return s;
    };
  };
  DistanceRequest full;
  full.tolerance = tolerance;
  v["full"] = kernel(full);
  DistanceRequest u5 = full;
  u5.upper_bound = 5;
  v["bounded-U5"] = kernel(u5);
  DistanceRequest np = full;
  np.pretests = false;
  v["no-pretests"] = kernel(np);
  DistanceRequest ns = full;
  ns.sorted_bounds = false;
  v["no-sorted-bounds"] = kernel(ns);
  v["naive"] = [repeat, tolerance](const CylinderPair& p) {
    DistanceResult r;
    Sample s = time_one(p, repeat, [&] { r = geometry::distance_naive(p.a, p.b, tolerance); return r.distance; });
    s.err = error_of(p, r.distance, false, 0);
    return s;
  };
  v["fcl"] = [repeat](const CylinderPair& p) {
    const FclPair f(p.a, p.b);
    double d = 0;
    Sample s = time_one(p, repeat, [&] { d = f.distance(); return d; });
    s.err = error_of(p, d, false, 0);
    return s;
  };
  v["segment-floor"] = [repeat](const CylinderPair& p) {
    const geometry::Segment sa{p.a.p0, p.a.p1}, sb{p.b.p0, p.b.p1};
    double d = 0;
    Sample s = time_one(p, repeat, [&] { d = geometry::closest_points(sa, sb).distance; return d; });
    // The capsule distance, for reference only: it is not a cylinder distance.
    s.err = error_of(p, std::max(0.0, d - p.a.radius - p.b.radius), false, 0);
    return s;
  };
  return v;
}

std::vector<Sample> run_variant(const Variant& variant, const std::vector<CylinderPair>& pairs) {
  std::vector<Sample> out;
  out.reserve(pairs.size());
  for (const auto& p : pairs) {
    Sample s = variant(p);
    s.rel_err = s.err / std::max(1.0, geometry::pair_scale(p.a, p.b));
    out.push_back(s);
  }
  return out;
}

std::map<std::string, std::vector<const Sample*>> group(const std::vector<Sample>& samples,
                                                        bool by_subtype) {
  std::map<std::string, std::vector<const Sample*>> g;
  for (const auto& s : samples) {
    g[by_subtype ? subtype_of(s.pair->id) : s.pair->category].push_back(&s);
    g["all"].push_back(&s);
  }
  return g;
}

std::vector<double> field(const std::vector<const Sample*>& v, double Sample::*m) {
  std::vector<double> out;
  out.reserve(v.size());
  for (const Sample* s : v) out.push_back(s->*m);
  return out;
}

}  // namespace

int bench_distance(const std::string& pairs_csv, const std::vector<std::string>& names, int repeat, double tolerance) {
  const auto pairs = read_pairs_csv(pairs_csv);
  std::cout.precision(6);
  auto variants = make_variants(repeat, tolerance);
  std::cout << "variant,category,n,median_ns,p99_ns,max_abs_err\n";
  for (const auto& name : names) {
    if (!variants.count(name)) throw std::runtime_error("unknown variant '" + name + "'");
    const auto samples = run_variant(variants[name], pairs);
    for (const auto& [cat, v] : group(samples, false)) {
      const auto ns = field(v, &Sample::ns), err = field(v, &Sample::err);
      std::cout << name << ',' << cat << ',' << v.size() << ',' << quantile(ns, 0.5) << ','
                << quantile(ns, 0.99) << ',' << *std::max_element(err.begin(), err.end()) << '\n';
    }
  }
  return 0;
}

int bench_tolerance(const std::string& pairs_csv, const std::vector<double>& tolerances, int repeat) {
  const auto pairs = read_pairs_csv(pairs_csv);
  std::cout.precision(6);
  std::cout << "tolerance,category,n,median_ns,max_abs_err,median_abs_err,max_rel_err\n";
  for (const double tol : tolerances) {
    const auto samples = run_variant(make_variants(repeat, tol)["full"], pairs);
    for (const auto& [cat, v] : group(samples, false)) {
      const auto ns = field(v, &Sample::ns), err = field(v, &Sample::err), rel = field(v, &Sample::rel_err);
      std::cout << tol << ',' << cat << ',' << v.size() << ',' << quantile(ns, 0.5) << ','
                << *std::max_element(err.begin(), err.end()) << ',' << quantile(err, 0.5) << ','
                << *std::max_element(rel.begin(), rel.end()) << '\n';
    }
  }
  return 0;
}

int bench_stiff(const std::string& pairs_csv, int repeat, double tolerance) {
  const auto pairs = read_pairs_csv(pairs_csv);
  std::cout.precision(6);
  const auto samples = run_variant(make_variants(repeat, tolerance)["full"], pairs);
  std::cout << "subtype,n,median_ns,max_abs_err,max_rel_err,worst_id\n";
  for (const auto& [sub, v] : group(samples, true)) {
    const Sample* worst =
        *std::max_element(v.begin(), v.end(), [](const Sample* x, const Sample* y) { return x->rel_err < y->rel_err; });
    const auto ns = field(v, &Sample::ns), err = field(v, &Sample::err);
    std::cout << sub << ',' << v.size() << ',' << quantile(ns, 0.5) << ',' << *std::max_element(err.begin(), err.end())
              << ',' << worst->rel_err << ',' << worst->pair->id << '\n';
  }
  return 0;
}

}  // namespace mtcs::bench
