// The part-mold coupling (eval/part_coupling.h) against a second method: a transient 1-D finite
// difference solution of the molded wall, cycle after cycle. A steel wall of depth d to a coolant
// at T_c takes the part's heat during fill, pack and cooling and none while the mold is open;
// repeated until periodic, its cycle-averaged flux and wall temperature are what the steady
// Robin condition q = h_p (T_m - T_w) with q = k (T_w - T_c) / d gives, within 2 %.

#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <vector>

#include "mtcs/eval/part_coupling.h"

using namespace mtcs;

namespace {

// Implicit Euler on cells in series: tridiagonal (Thomas) per step.
struct Rod {
  std::vector<double> capacity;  // J/K per mm^2, per cell
  std::vector<double> link;      // W/(mm^2 K) between cell i and i + 1
  double end_film = 0;           // last cell to the fixed end temperature
  double end_temperature = 0;

  void step(std::vector<double>& T, double dt, int open_link) const {
    const std::size_t n = T.size();
    std::vector<double> a(n, 0.0), b(n, 0.0), c(n, 0.0), r(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) b[i] = capacity[i] / dt, r[i] = capacity[i] / dt * T[i];
    for (std::size_t i = 0; i + 1 < n; ++i) {
      if (int(i) == open_link) continue;
      b[i] += link[i], b[i + 1] += link[i], c[i] -= link[i], a[i + 1] -= link[i];
    }
    b[n - 1] += end_film, r[n - 1] += end_film * end_temperature;
    for (std::size_t i = 1; i < n; ++i) {
      const double w = a[i] / b[i - 1];
      b[i] -= w * c[i - 1], r[i] -= w * r[i - 1];
    }
    T[n - 1] = r[n - 1] / b[n - 1];
    for (std::size_t i = n - 1; i-- > 0;) T[i] = (r[i] - c[i] * T[i + 1]) / b[i];
  }
};

struct Periodic {
  double flux = 0;         // W/mm^2, cycle-averaged into the steel
  double wall = 0;         // degrees C, the cavity wall's cycle average
};

// Half the part (its mid-plane a symmetry plane) on steel of depth d to the coolant.
Periodic periodic_wall(const mold::Polymer& p, double s, double d, double fill_pack_cool, double open, double coolant) {
  const double rho_cp = p.density * p.specific_heat * 1e-9, k_p = p.diffusivity * rho_cp;
  const double k_s = 0.03, rho_cp_s = 7800 * 460 * 1e-9;
  const int np = 40, ns = 120;
  const double dxp = s / 2 / np, dxs = d / ns;
  Rod rod;
  for (int i = 0; i < np; ++i) rod.capacity.push_back(rho_cp * dxp);
  for (int i = 0; i < ns; ++i) rod.capacity.push_back(rho_cp_s * dxs);
  for (int i = 0; i + 1 < np + ns; ++i) {
    const double ka = i < np ? k_p : k_s, kb = i + 1 < np ? k_p : k_s;
    const double da = i < np ? dxp : dxs, db = i + 1 < np ? dxp : dxs;
    rod.link.push_back(1 / (da / 2 / ka + db / 2 / kb));
  }
  rod.end_film = k_s / (dxs / 2), rod.end_temperature = coolant;
  const double dt = 0.005;
  const int n_in = int(std::lround(fill_pack_cool / dt)), n_open = int(std::lround(open / dt));
  const double cycle = (n_in + n_open) * dt;
  // The wall's temperature: the interface between the last plastic cell and the first steel one.
  const double gp = k_p / (dxp / 2), gs = k_s / (dxs / 2);
  std::vector<double> T(std::size_t(np + ns), coolant);
  Periodic last{-1, -1};
  for (int n = 0; n < 2000; ++n) {
    for (int i = 0; i < np; ++i) T[std::size_t(i)] = p.melt_temperature;
    double heat = 0, wall = 0;
    for (int t = 0; t < n_in; ++t) {
      rod.step(T, dt, -1);
      heat += rod.link[np - 1] * (T[np - 1] - T[np]) * dt;
      wall += (gp * T[np - 1] + gs * T[np]) / (gp + gs) * dt;
    }
    for (int t = 0; t < n_open; ++t) {
      rod.step(T, dt, np - 1);
      wall += T[np] * dt;  // adiabatic: the face at its cell's temperature
    }
    const Periodic now{heat / cycle, wall / cycle};
    if (std::abs(now.flux - last.flux) < 1e-9 * now.flux && std::abs(now.wall - last.wall) < 1e-7) return now;
    last = now;
  }
  FAIL("the cycles did not become periodic");
  return last;
}

}  // namespace

TEST_CASE("part coupling: the slab's mean at ejection is the series' first terms, and its bounds", "[eval][coupling]") {
  constexpr double pi = std::numbers::pi;
  for (const double fo : {0.05, 0.1, 0.22, 0.5}) {
    const double three = 8 / (pi * pi) * std::exp(-pi * pi * fo) + 8 / (9 * pi * pi) * std::exp(-9 * pi * pi * fo) +
                         8 / (25 * pi * pi) * std::exp(-25 * pi * pi * fo);
    CHECK(eval::slab_mean_fraction(fo) == Approx(three).epsilon(1e-4));
  }
  // Fo -> 0: sum 8 / (n^2 pi^2) over odd n is 1 (the slab still at the melt).
  CHECK(eval::slab_mean_fraction(1e-6) == Approx(1).epsilon(3e-3));
  CHECK(eval::slab_odd_buildup(10) == Approx(1).epsilon(1e-9));
  CHECK(eval::slab_odd_buildup(1e-8) < 1e-3);
}

TEST_CASE("part coupling: h_p for the ABS defaults, worked by hand", "[eval][coupling]") {
  // s 2.5 mm, t_in 14.5 s, cycle 19.5 s: Fo = 0.095 * 14.5 / 6.25 = 0.2204,
  // theta = 8/pi^2 exp(-pi^2 0.2204) = 0.09139, h_p = 1050 * 2000 * 0.0025 * 0.90861 / 39 = 122.3 W/(m^2 K).
  const eval::PartCoupling c = eval::part_coupling(mold::Polymer{}, 2.5, 14.5, 19.5);
  CHECK(c.film * 1e6 == Approx(122.3).epsilon(2e-3));
  CHECK(c.temperature == 230);
  // h_x = (k_p t_in / s + rho c_p s / 12) / t_cycle - h_p / 2
  //     = (0.1995 * 14.5 / 0.0025 + 5250 / 12) / 19.5 - 61.15 = 81.77 - 61.15 = 20.6.
  CHECK(c.cross_film * 1e6 == Approx(20.6).epsilon(5e-3));
  CHECK_THROWS_AS(eval::part_coupling(mold::Polymer{}, 0, 14.5, 19.5), std::invalid_argument);
  CHECK_THROWS_AS(eval::part_coupling(mold::Polymer{}, 2.5, 20, 19.5), std::invalid_argument);
}

TEST_CASE("part coupling: the Robin condition is the periodic transient's cycle average within 2 %", "[eval][coupling]") {
  const mold::Polymer abs;
  struct Case {
    double s, d, in_mold, open;
  };
  // Thin and thick walls, near and far coolant (wall 44 to 77 degrees C), long and short opens.
  for (const Case& c : {Case{2.5, 12, 14.5, 5}, Case{2.5, 60, 14.5, 5}, Case{1.0, 12, 8, 5}, Case{4.0, 30, 30, 2}}) {
    CAPTURE(c.s, c.d, c.in_mold, c.open);
    const double coolant = 40, k_s = 0.03;
    const Periodic fd = periodic_wall(abs, c.s, c.d, c.in_mold, c.open, coolant);
    const eval::PartCoupling robin = eval::part_coupling(abs, c.s, c.in_mold, c.in_mold + c.open);
    const double wall = (robin.film * robin.temperature + k_s / c.d * coolant) / (robin.film + k_s / c.d);
    const double flux = robin.film * (robin.temperature - wall);
    CHECK(flux == Approx(fd.flux).epsilon(0.02));
    CHECK((wall - coolant) == Approx(fd.wall - coolant).epsilon(0.02));
    CHECK(wall < robin.temperature);
  }
}

TEST_CASE("part coupling: walls at two temperatures exchange heat through the part as h_x says", "[eval][coupling]") {
  // The whole part between walls fixed at T1 and T2, one in-mold time from the melt: the heat into
  // wall 1 is (h_p (T_m - T1) + h_x (T2 - T1)) t_cycle.
  const mold::Polymer abs;
  const double s = 2.5, t_in = 14.5, cycle = 19.5, T1 = 45, T2 = 75;
  const double rho_cp = abs.density * abs.specific_heat * 1e-9, k_p = abs.diffusivity * rho_cp;
  const int n = 200;
  const double dx = s / n, dt = 0.002;
  std::vector<double> T(n, abs.melt_temperature);
  const double g = k_p / dx, g_end = k_p / (dx / 2);
  double heat1 = 0;
  for (int step = 0; step < int(std::lround(t_in / dt)); ++step) {
    // Implicit Euler, Thomas; ends to T1 (cell 0) and T2 (cell n - 1).
    std::vector<double> a(n, -g), b(n, rho_cp * dx / dt + 2 * g), c(n, -g), r(n);
    for (int i = 0; i < n; ++i) r[std::size_t(i)] = rho_cp * dx / dt * T[std::size_t(i)];
    b[0] = rho_cp * dx / dt + g + g_end, r[0] += g_end * T1;
    b[n - 1] = rho_cp * dx / dt + g + g_end, r[n - 1] += g_end * T2;
    for (int i = 1; i < n; ++i) {
      const double w = a[std::size_t(i)] / b[std::size_t(i - 1)];
      b[std::size_t(i)] -= w * c[std::size_t(i - 1)], r[std::size_t(i)] -= w * r[std::size_t(i - 1)];
    }
    T[n - 1] = r[n - 1] / b[n - 1];
    for (int i = n - 1; i-- > 0;) T[std::size_t(i)] = (r[std::size_t(i)] - c[std::size_t(i)] * T[std::size_t(i + 1)]) / b[std::size_t(i)];
    heat1 += g_end * (T[0] - T1) * dt;
  }
  const eval::PartCoupling c = eval::part_coupling(abs, s, t_in, cycle);
  const double model = (c.film * (c.temperature - T1) + c.cross_film * (T2 - T1)) * cycle;
  CHECK(model == Approx(heat1).epsilon(0.01));
  // The odd part alone: the difference between the two walls' heats is 2 h_x (T2 - T1) t_cycle.
  CHECK(c.cross_film > 0);
}

TEST_CASE("part coupling: the consistent cooling time where plain substitution oscillates", "[eval][coupling]") {
  // A steep, decreasing need (the L-bracket's whole solves: 235, 77, 216, 79, 191 s from 75 s):
  // substitution c <- need(c) swings around the root; regula falsi closes in on it.
  const auto need = [](double c) { return 60 + 175 * std::exp(-(c - 75) / 12); };
  double c = 75;
  for (int i = 0; i < 6; ++i) c = need(c);
  const double root = eval::consistent_cooling(need, 75, 1e-6, 40);
  INFO("substitution after 6 steps " << c << " s, root " << root << " s, need there " << need(root));
  CHECK(std::abs(need(c) - c) > 0.2 * c);  // the oscillation this replaces
  CHECK(need(root) == Approx(root).epsilon(1e-6));
  int evaluations = 0;
  const double coarse = eval::consistent_cooling(need, 75, 0.01, 6, &evaluations);
  CHECK(evaluations <= 6);
  CHECK(need(coarse) == Approx(coarse).epsilon(0.01));
  // Already consistent: one evaluation.
  CHECK(eval::consistent_cooling([](double) { return 20.0; }, 20, 0.01, 6, &evaluations) == 20);
  CHECK(evaluations == 1);
}

TEST_CASE("part coupling: a known point and a start predicted from it bracket the cooling time", "[eval][coupling]") {
  // mtcs thermal's cycle: the nominal solve (75 s, need 235 s: need > c) predicts a start past
  // the root (need < c); the two bracket it, and the search takes fewer new evaluations than from
  // the start alone (the known point counts as one).
  const auto need = [](double c) { return 60 + 175 * std::exp(-(c - 75) / 12); };
  const double root = eval::consistent_cooling(need, 75, 1e-9, 60);
  const double start = 1.05 * root;
  int alone = 0, bracketed = 0;
  const double c0 = eval::consistent_cooling(need, start, 1e-4, 20, &alone);
  const double c1 = eval::consistent_cooling(need, start, 1e-4, 20, &bracketed, std::pair(75.0, need(75)));
  INFO(alone << " evaluations alone, " << bracketed - 1 << " new ones with the known point");
  CHECK(need(c0) == Approx(c0).epsilon(1e-4));
  CHECK(need(c1) == Approx(c1).epsilon(1e-4));
  CHECK(bracketed - 1 < alone);
  // A known point on the start's side (0.97 root: need > c, as at 75 s) brackets nothing: the
  // search is the one from the start, one evaluation more for the known point.
  int same_side = 0;
  CHECK(eval::consistent_cooling(need, 0.97 * root, 1e-4, 20, &same_side, std::pair(75.0, need(75))) ==
        eval::consistent_cooling(need, 0.97 * root, 1e-4, 20, &alone));
  CHECK(same_side == alone + 1);
  // A known point within the tolerance is the answer: nothing more is evaluated.
  int none = 0;
  const auto never = [](double) -> double { FAIL("need evaluated"); return 0; };
  CHECK(eval::consistent_cooling(never, 2 * root, 1e-4, 20, &none, std::pair(root, need(root))) == root);
  CHECK(none == 1);
}
