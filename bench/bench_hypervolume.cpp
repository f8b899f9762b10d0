// mtcs bench hypervolume: ours against pagmo 2.18 in the same run, on the fronts of a folder
// (shared/cases/hv_fronts format): hypervolume and all contributions, time and agreement.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include "bench_hypervolume.h"
#include "mtcs/io/front_file.h"
#include "mtcs/opt/hypervolume.h"
#include "pagmo_peer.h"

namespace mtcs::bench {
namespace {

namespace fs = std::filesystem;

// Seconds per call of ours and theirs: medians of `repeat` samples (at least one) taken in
// turns, so that load from elsewhere hits both alike; each sample as many calls as fill 2 ms,
// so that microsecond calls are not timer noise.
template <class F, class G>
std::pair<double, double> timed(int repeat, F&& ours, G&& theirs) {
  using Clock = std::chrono::steady_clock;
  const auto batch = [](auto& f) {
    const auto t0 = Clock::now();
    f();
    const double once = std::chrono::duration<double>(Clock::now() - t0).count();
    return once >= 2e-3 ? 1 : int(std::min(1e5, 2e-3 / std::max(once, 1e-8)));
  };
  const int n_ours = batch(ours), n_theirs = batch(theirs);
  const auto sample = [](auto& f, int calls) {
    const auto start = Clock::now();
    for (int c = 0; c < calls; ++c) f();
    return std::chrono::duration<double>(Clock::now() - start).count() / calls;
  };
  std::vector<double> a, b;
  for (int i = 0; i < std::max(1, repeat); ++i) {
    a.push_back(sample(ours, n_ours));
    b.push_back(sample(theirs, n_theirs));
  }
  const auto median = [](std::vector<double>& t) {
    std::nth_element(t.begin(), t.begin() + long(t.size() / 2), t.end());
    return t[t.size() / 2];
  };
  return {median(a), median(b)};
}

}  // namespace

int bench_hypervolume(const std::string& dir, int repeat, std::size_t max_contribution_n) {
  std::map<std::string, double> expected;
  {
    std::ifstream in(fs::path(dir) / "expected.csv");
    std::string line;
    std::getline(in, line);
    while (std::getline(in, line)) {
      std::istringstream ss(line);
      std::string name, d, n, hv;
      std::getline(ss, name, ','), std::getline(ss, d, ','), std::getline(ss, n, ','), std::getline(ss, hv, ',');
      expected[name] = std::stod(hv);
    }
  }
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".txt") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  std::cout << "front,d,n,ours_hv_s,pagmo_hv_s,hv_speedup,ours_err,pagmo_err,ours_contrib_s,pagmo_contrib_s,"
               "contrib_speedup,contrib_max_rel_diff\n";
  std::cout.precision(4);
  for (const auto& path : files) {
    const io::FrontFile f = io::read_front(path.string());
    const std::string name = path.stem().string();
    double ours = 0, theirs = 0;
    const auto [t_ours, t_theirs] = timed(
        repeat, [&] { ours = opt::hypervolume(f.points, f.ref); }, [&] { theirs = pagmo_hypervolume(f.points, f.ref); });
    const double want = expected.count(name) ? expected[name] : ours;
    std::cout << name << ',' << f.ref.size() << ',' << f.points.size() << ',' << t_ours << ',' << t_theirs << ','
              << t_theirs / t_ours << ',' << std::abs(ours - want) / want << ',' << std::abs(theirs - want) / want;
    if (f.points.size() <= max_contribution_n) {
      std::vector<double> co, cp;
      const auto [tc_ours, tc_theirs] = timed(
          repeat, [&] { co = opt::contributions(f.points, f.ref); }, [&] { cp = pagmo_contributions(f.points, f.ref); });
      double worst = 0;
      for (std::size_t i = 0; i < co.size(); ++i)
        worst = std::max(worst, std::abs(co[i] - cp[i]) / std::max(1e-300, std::max(std::abs(co[i]), std::abs(cp[i]))));
      std::cout << ',' << tc_ours << ',' << tc_theirs << ',' << tc_theirs / tc_ours << ',' << worst;
    } else {
      std::cout << ",,,,";
    }
    std::cout << '\n';
  }
  return 0;
}

}  // namespace mtcs::bench
