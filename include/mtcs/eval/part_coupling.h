#pragma once
// The part-mold coupling: how much heat the molded part gives a mold wall, as a function of the
// wall's cycle-averaged temperature (docs/thermal-model.md, "The cavity condition").
//
// A wall of thickness s between two mold walls, injected at the melt temperature T_m, stays in
// the mold for t_in = fill + pack + cooling and leaves it; the mold is then open for t_open
// (the wall takes no heat), the cycle lasts t_cycle = t_in + t_open. With both walls at T_w,
// the slab's mean temperature at ejection is T_w + (T_m - T_w) theta(Fo), Fo = alpha t_in / s^2,
// theta the first-kind series below (Carslaw and Jaeger 3.3). Each wall takes half the heat
// the slab gives up, once per cycle, so its cycle-averaged flux is linear in its temperature:
//
//   q = h_p (T_m - T_w),  h_p = rho c_p s (1 - theta(Fo)) / (2 t_cycle)     (a Robin condition)
//
// and no wall can be hotter than T_m. With the walls at T_1 and T_2, the slab is its even part
// (both walls at their mean) plus its odd part (walls at -+(T_2 - T_1) / 2, starting from 0),
// which conducts across the wall, the same on both sides and linear too:
//
//   q_1 += h_x (T_2 - T_1),  h_x = (k_p t_in / s + rho c_p s S(Fo) / 12) / t_cycle - h_p / 2
//
// S(Fo) = (6 / pi^2) sum_m (1 - exp(-4 m^2 pi^2 Fo)) / m^2, the odd profile's build-up (0 to 1);
// the - h_p / 2 moves the even part's wall temperature from the mean to T_1. h_x -> 0 for short
// contacts, where each wall sees a half-space of melt.
// Checked against a transient 1-D slab in steel, cycle after cycle until periodic
// (tests/eval/part_coupling_test.cpp): the cycle-averaged flux within 2 %.
//
// Units: mm, s, W, degrees C (films W/(mm^2 K)), as the thermal module.

#include <functional>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "mtcs/mold/mold_spec.h"

namespace mtcs::eval {

// The slab's mean temperature at ejection as a fraction of its start, above the walls:
// theta(Fo) = sum over odd n of 8 / (n^2 pi^2) exp(-n^2 pi^2 Fo). 1 at Fo = 0.
double slab_mean_fraction(double fourier);
// S(Fo) above: 0 at Fo = 0, 1 as Fo grows.
double slab_odd_buildup(double fourier);

// The cavity condition at one place of the part.
struct PartCoupling {
  double film = 0;          // h_p, W/(mm^2 K)
  double temperature = 0;   // T_p, degrees C: the melt's
  double cross_film = 0;    // h_x, W/(mm^2 K), between a shell's two faces
};

// h_p, T_p and h_x of a wall `thickness` mm thick in a cycle whose part stays `in_mold` s in
// the mold and `cycle` s in all. Throws std::invalid_argument unless 0 < in_mold <= cycle and
// thickness > 0.
PartCoupling part_coupling(const mold::Polymer& polymer, double thickness, double in_mold, double cycle);

// The spec's cycle in seconds: in the mold (fill + pack + cooling) and in all (+ open). The
// cooling time: thermal.cycle.cooling, else the cooling time of the spec's wall with the mold
// wall at the coolant's temperature (eval::cooling_time), the shortest the part can have.
struct CycleTimes {
  double in_mold = 0, cycle = 0, cooling = 0;
};
CycleTimes nominal_cycle(const mold::MoldSpec& spec);

// The condition the spec asks for everywhere outside thermal.regions: thermal.part_film and
// thermal.part_temperature where given, else part_coupling at the cavity's wall thickness and
// the nominal cycle.
PartCoupling cavity_coupling(const mold::MoldSpec& spec);

// The cooling time c that a mold's solution needs when its film is derived for c itself:
// need(c) = c, `need` decreasing in c (a longer cycle, a weaker film, a cooler mold, a shorter
// cooling). Plain substitution oscillates where need is steep (the L-bracket: 77, 216, 79, 191
// s); regula falsi (Illinois) in logarithms on the bracket [c0, need(c0)] converges in a few
// evaluations (need > 0). Stops
// when |need(c) - c| <= tolerance c or after max_evaluations of need (then the c with the least
// misfit). `evaluations` (optional) counts them. `known` (optional): a cooling time and its
// need, already evaluated (`start` predicted from it), counted among the evaluations: within
// tolerance it is the answer; when it and `start` bracket the root, the search starts from that
// bracket (one evaluation fewer than a substitution step).
double consistent_cooling(const std::function<double(double)>& need, double start, double tolerance,
                          int max_evaluations, int* evaluations = nullptr,
                          std::optional<std::pair<double, double>> known = {});

// The cycle a solution needs, from that one solve (the optimiser's linearisation of the fixed
// point mtcs thermal iterates with whole solves; docs/thermal-model.md, "The cycle in the
// optimiser"). Each sample's wall is read as a 1-D link of unknown conductance G to the coolant
// behind a film h to T_p: its share r = (T - T_c) / (T_p - T_c) = h / (h + G) fixes G, and a
// film x h gives r' = x r / (x r + 1 - r). The hottest sample stays the hottest; its cooling
// time sets the cycle, the cycle the film, until the cooling time moves by less than 0.1 %.
// `temperature` (solved with the nominal film) becomes that film's; its first `deciding` values
// (the samples; the rest, points across the part, follow) set the hottest. Samples in a fixed-
// flux region are rescaled as well: an approximation where regions meet the cavity. Nothing
// changes unless the cavity is coupled with a derived film and cycle (no thermal.part_film,
// no thermal.cycle.cooling); the answer stands at the last film once the wall is too hot to
// eject. With the part's local wall (`thickness` per value, cavity.wall_thickness: local) the
// place that cools last (eval::slowest_place) takes the hottest's part, its wall the film's
// thickness; the film's ratio at that wall rescales every sample (the thin walls' ratio
// differs by the slab's residual heat, a few % at Fo < 0.2). Returns the cooling time (s).
double follow_cycle(std::vector<double>& temperature, const mold::MoldSpec& spec, std::size_t deciding,
                    std::span<const double> thickness = {});

}  // namespace mtcs::eval
