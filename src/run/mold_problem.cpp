#include "mtcs/run/mold_problem.h"

#include <algorithm>
#include <cmath>

#include "aim_bores.h"
#include "holes.h"
#include "mtcs/eval/thermal_model.h"
#include "mtcs/mold/decoder.h"
#include "reach_move.h"
#include "violation_text.h"

namespace mtcs::run {

using geometry::Vec3;

using mold::axis_of;
using mold::face_plane;

namespace {

// A circuit's diameter slot holds its diameter's index plus kKindCode times its kind (0 drilled,
// 1 baffle, 2 bubbler): genotypes stored before baffles read as drilled.
constexpr int kKindCode = 100;

mold::CircuitKind kind_of_code(int code) {
  switch (code / kKindCode) {
    case 1: return mold::CircuitKind::Baffle;
    case 2: return mold::CircuitKind::Bubbler;
    default: return mold::CircuitKind::Drilled;
  }
}

// The index of the k-th circuit that is (or is not) blind.
std::size_t nth_circuit(const mold::Genome& g, bool blind, int k) {
  for (std::size_t i = 0; i < g.circuits.size(); ++i)
    if (is_blind(g.circuits[i].kind) == blind && k-- == 0) return i;
  return g.circuits.size();
}

}  // namespace

MoldProblem::MoldProblem(const eval::Pipeline& pipeline, std::vector<double> weights, MutationRates rates,
                         std::optional<mold::PenaltyVariant> penalty, const eval::Pipeline* screen)
    : pipeline_(pipeline), screen_(screen), spec_(pipeline.scene().spec()), block_(pipeline.scene().block_bounds()),
      weights_(std::move(weights)), rates_(rates), initial_step_(0.1 * block_.size().minCoeff()) {
  ranking_.objectives = spec_.objectives;
  ranking_.penalty = spec_.penalty;
  if (penalty) ranking_.penalty.variant = *penalty;
  if (rates_.access_guided && !spec_.drilling.axis_parallel) access_ = pipeline.drill_access();
  region_ = block_;
  if (spec_.cavity) {
    const geometry::Box part = spec_.cavity->box ? *spec_.cavity->box : spec_.cavity->mesh->mesh.bounds();
    const double reach = 4 * *std::max_element(spec_.drilling.diameters.begin(), spec_.drilling.diameters.end());
    region_ = {(part.min - Vec3::Constant(reach)).cwiseMax(block_.min), (part.max + Vec3::Constant(reach)).cwiseMin(block_.max)};
  }
  const auto& use = spec_.objectives.use;
  if (rates_.reach > 0 && spec_.cavity && std::find(use.begin(), use.end(), mold::Objective::WorstCovered) != use.end())
    reach_.emplace(eval::thermal_samples(pipeline.scene()).points, block_.min);
}

mold::Genome MoldProblem::genome(const opt::Genotype& g) const {
  mold::Genome out;
  std::size_t i = 0;
  const int circuits = int(g[i++]);
  const auto& diameters = spec_.drilling.diameters;
  out.circuits.reserve(std::size_t(std::max(circuits, 0)));  // one allocation each, not one per doubling
  for (int c = 0; c < circuits; ++c) {
    mold::Circuit circuit;
    const int code = std::max(int(g[i++]), 0);
    circuit.kind = kind_of_code(code);
    circuit.diameter = diameters[std::size_t(std::clamp(code % kKindCode, 0, int(diameters.size()) - 1))];
    const int n = int(g[i++]);
    circuit.waypoints.reserve(std::size_t(std::max(n, 0)));
    for (int p = 0; p < n; ++p, i += 3) circuit.waypoints.emplace_back(g[i], g[i + 1], g[i + 2]);
    out.circuits.push_back(std::move(circuit));
  }
  return out;
}

std::size_t MoldProblem::dimension(const opt::Genotype& g) const {
  const std::size_t circuits = std::size_t(g[0]);
  return g.size() - 1 - 2 * circuits;
}

opt::Genotype MoldProblem::encode(const mold::Genome& genome) const {
  std::size_t size = 1;
  for (const auto& c : genome.circuits) size += 2 + 3 * c.waypoints.size();
  opt::Genotype g;
  g.reserve(size);  // the genotype's exact length: one allocation
  g.push_back(double(genome.circuits.size()));
  const auto& diameters = spec_.drilling.diameters;
  for (const auto& c : genome.circuits) {
    const auto it = std::min_element(diameters.begin(), diameters.end(),
                                     [&](double a, double b) { return std::abs(a - c.diameter) < std::abs(b - c.diameter); });
    g.push_back(double(it - diameters.begin()) + kKindCode * double(int(c.kind)));
    g.push_back(double(c.waypoints.size()));
    for (const Vec3& p : c.waypoints) g.insert(g.end(), {p.x(), p.y(), p.z()});
  }
  return g;
}

mold::Circuit MoldProblem::random_circuit(opt::Rng& rng) const {
  // A U (or an L between different faces): in from the inlet face, across, out to the outlet
  // face, in one plane, around the part (within a few diameters of its box). The shape every
  // drilled circuit is made of, and free of self-crossings.
  const geometry::Box& r = region_;
  auto within = [&](int k) { return r.min[k] + rng.uniform() * r.size()[k]; };
  const mold::Face in = spec_.circuits.inlet_faces[std::size_t(rng.below(int(spec_.circuits.inlet_faces.size())))];
  const mold::Face out = spec_.circuits.outlet_faces[std::size_t(rng.below(int(spec_.circuits.outlet_faces.size())))];
  const int ki = axis_of(in), ko = axis_of(out);
  Vec3 p(within(0), within(1), within(2));
  mold::Circuit c;
  c.diameter = spec_.drilling.diameters[std::size_t(rng.below(int(spec_.drilling.diameters.size())))];
  Vec3 inlet = p;
  inlet[ki] = face_plane(block_, in);
  c.waypoints.push_back(inlet);
  c.waypoints.push_back(p);  // straight in
  if (ki == ko) {
    // Across along another drillable axis, then straight out through the same face.
    std::vector<int> axes;
    for (const mold::Face f : spec_.drilling.allowed_faces)
      if (axis_of(f) != ki && std::find(axes.begin(), axes.end(), axis_of(f)) == axes.end()) axes.push_back(axis_of(f));
    const int across = axes.empty() ? (ki + 1) % 3 : axes[std::size_t(rng.below(int(axes.size())))];
    Vec3 q = p;
    q[across] = within(across);
    c.waypoints.push_back(q);
    q[ko] = face_plane(block_, out);
    c.waypoints.push_back(q);
  } else {
    Vec3 q = p;
    q[ko] = face_plane(block_, out);
    c.waypoints.push_back(q);
  }
  if (access_) {
    aim_bores(*access_, pipeline_.scene(), c, rng);
    repair(c);
  }
  return c;
}

mold::Circuit MoldProblem::random_blind(opt::Rng& rng) const {
  // Straight down from a baffle face, over the part, its tip anywhere across the part's depth.
  const mold::BaffleSpec& b = *spec_.drilling.baffles;
  const geometry::Box& r = region_;
  mold::Circuit c;
  c.kind = b.kinds[std::size_t(rng.below(int(b.kinds.size())))];
  c.diameter = spec_.drilling.diameters[std::size_t(rng.below(int(spec_.drilling.diameters.size())))];
  const mold::Face face = b.faces[std::size_t(rng.below(int(b.faces.size())))];
  Vec3 entry(r.min.x() + rng.uniform() * r.size().x(), r.min.y() + rng.uniform() * r.size().y(),
             r.min.z() + rng.uniform() * r.size().z());
  Vec3 tip = entry;
  entry[axis_of(face)] = face_plane(block_, face);
  c.waypoints = {entry, tip};
  repair(c);
  return c;
}

opt::Genotype MoldProblem::sample(opt::Rng& rng) const {
  mold::Genome g;
  const int k = spec_.circuits.min + rng.below(spec_.circuits.max - spec_.circuits.min + 1);
  for (int c = 0; c < k; ++c) g.circuits.push_back(random_circuit(rng));
  if (spec_.drilling.baffles)
    for (int n = rng.below(spec_.drilling.baffles->max + 1); n > 0; --n) g.circuits.push_back(random_blind(rng));
  return encode(g);
}

void MoldProblem::repair(mold::Circuit& c) const {
  if (is_blind(c.kind)) {
    // The drilled axis (entry on its face, the tip straight below, at least a diameter deep).
    const mold::BlindAxis a = mold::blind_axis(pipeline_.scene(), c);
    c.waypoints = {a.entry, a.tip};
    return;
  }
  for (Vec3& p : c.waypoints) p = p.cwiseMax(block_.min).cwiseMin(block_.max);
  auto snap = [&](Vec3& p, const std::vector<mold::Face>& faces) {
    mold::Face best = faces.front();
    for (const mold::Face f : faces)
      if (std::abs(p[axis_of(f)] - face_plane(block_, f)) < std::abs(p[axis_of(best)] - face_plane(block_, best))) best = f;
    p[axis_of(best)] = face_plane(block_, best);
  };
  snap(c.waypoints.front(), spec_.circuits.inlet_faces);
  snap(c.waypoints.back(), spec_.circuits.outlet_faces);
}

namespace {
// The reach move's tries per diameter (two diameters at most), and the constraint check after.
constexpr int kReachTries = 12;
constexpr long kReachSpendsAtMost = 2 * kReachTries + 1;
}  // namespace

long MoldProblem::mutate(opt::Genotype& x, const std::vector<double>& steps, opt::Rng& rng) const {
  return mutate_within(x, steps, rng, std::numeric_limits<long>::max());
}

long MoldProblem::mutate_within(opt::Genotype& x, const std::vector<double>& steps, opt::Rng& rng,
                                long may_spend) const {
  mold::Genome g = genome(x);
  // The reach move alone: a child that moves other holes too would lose a narrow window it found.
  long spent = 0;
  if (reach_ && !reach_->empty() && rng.uniform() < rates_.reach && may_spend >= kReachSpendsAtMost &&
      reach_worst(g, rng, spent)) {
    x = encode(g);
    return spent;
  }
  const double sigma = steps.front();
  const auto& lim = spec_.circuits;
  // With mutation.moves, each hole (a run of aligned waypoints) or waypoint moves with the
  // probability that moves `moves` of them on average: a child keeps most of its parent's bores.
  int parts = 0, moved = 0;
  if (rates_.moves > 0)
    for (const auto& c : g.circuits) parts += movable_parts(c);
  const double move_probability = parts > 0 ? std::min(1.0, rates_.moves / parts) : 1.0;
  // Structural moves (circuits.min and max count the drilled circuits; drilling.baffles.max the blind).
  if (rng.uniform() < rates_.circuit) {
    const int drilled = int(g.circuits.size()) - count_blind(g);
    if (drilled < lim.max && (rng.uniform() < 0.5 || drilled <= lim.min))
      g.circuits.push_back(random_circuit(rng));
    else if (drilled > lim.min)
      g.circuits.erase(g.circuits.begin() + std::ptrdiff_t(nth_circuit(g, false, rng.below(drilled))));
  }
  if (spec_.drilling.baffles && rng.uniform() < rates_.baffle) {
    const int blind = count_blind(g);
    if (blind < spec_.drilling.baffles->max && (rng.uniform() < 0.5 || blind == 0))
      g.circuits.push_back(random_blind(rng));
    else if (blind > 0)
      g.circuits.erase(g.circuits.begin() + std::ptrdiff_t(nth_circuit(g, true, rng.below(blind))));
  }
  for (auto& c : g.circuits) {
    auto& w = c.waypoints;
    if (is_blind(c.kind)) {
      // One hole: a bigger or smaller drill, the entry across the face, the tip deeper or shallower.
      if (rng.uniform() < rates_.diameter) step_diameter(c, rng);
      moved += move_some(c, sigma, rates_.moves > 0 ? move_probability : 1.0, rng);
      repair(c);
      continue;
    }
    if (rng.uniform() < rates_.insert && int(w.size()) < lim.max_waypoints) {
      const int seg = rng.below(int(w.size()) - 1);
      const Vec3 p = w[std::size_t(seg)] + rng.uniform() * (w[std::size_t(seg + 1)] - w[std::size_t(seg)]);
      w.insert(w.begin() + seg + 1, p);
    }
    if (rates_.jog > 0 && spec_.drilling.axis_parallel && rng.uniform() < rates_.jog &&
        int(w.size()) + 2 <= lim.max_waypoints)
      jog(c, rng);
    if (rng.uniform() < rates_.remove && int(w.size()) > std::max(2, lim.min_waypoints) && w.size() > 2)
      w.erase(w.begin() + 1 + rng.below(int(w.size()) - 2));
    if (rng.uniform() < rates_.snap && w.size() > 2) {
      const int i = 1 + rng.below(int(w.size()) - 2);
      const int k = rng.below(3);
      w[std::size_t(i)][k] = w[std::size_t(i - 1)][k];
    }
    if (rng.uniform() < rates_.diameter) step_diameter(c, rng);
    if (rates_.moves > 0) {
      moved += move_some(c, sigma, move_probability, rng);
    } else if (spec_.drilling.axis_parallel) {
      // Move holes, not points: along each axis, consecutive waypoints that share the
      // coordinate (the ends of a hole across it) shift together, so aligned holes stay
      // aligned instead of breaking into zig-zags.
      for (int k = 0; k < 3; ++k)
        for_each_aligned_run(w, k, [&](std::size_t first, std::size_t last) {
          const double shift = sigma * rng.normal();
          for (std::size_t m = first; m < last; ++m) w[m][k] += shift;
        });
    } else {
      for (Vec3& p : w) p += sigma * Vec3(rng.normal(), rng.normal(), rng.normal());
    }
    repair(c);  // the ports back on their faces, everything inside the block
    if (access_) {
      aim_bores(*access_, pipeline_.scene(), c, rng);
      repair(c);
    }
  }
  if (rates_.moves > 0 && moved == 0 && !g.circuits.empty()) {
    // Every child moves something: one circuit, all of whose moves are then certain.
    mold::Circuit& c = g.circuits[std::size_t(rng.below(int(g.circuits.size())))];
    move_some(c, sigma, 1.0, rng);
    repair(c);
    if (access_ && !is_blind(c.kind)) {
      aim_bores(*access_, pipeline_.scene(), c, rng);
      repair(c);
    }
  }
  x = encode(g);
  return spent;
}

void MoldProblem::step_diameter(mold::Circuit& c, opt::Rng& rng) const {
  const auto& d = spec_.drilling.diameters;
  int idx = int(std::find(d.begin(), d.end(), c.diameter) - d.begin());
  idx = std::clamp(idx + (rng.uniform() < 0.5 ? -1 : 1), 0, int(d.size()) - 1);
  c.diameter = d[std::size_t(idx)];
}

void MoldProblem::jog(mold::Circuit& c, opt::Rng& rng) const {
  auto& w = c.waypoints;
  const std::size_t seg = std::size_t(rng.below(int(w.size()) - 1));
  const Vec3 a = w[seg], b = w[seg + 1];
  int along = 0;
  (b - a).cwiseAbs().maxCoeff(&along);
  // Across: an axis the circuit already spans other than the segment's (its drilling plane).
  std::vector<int> across;
  for (int k = 0; k < 3; ++k) {
    bool spans = false;
    for (const Vec3& p : w) spans = spans || p[k] != w.front()[k];
    if (k != along && spans) across.push_back(k);
  }
  if (across.empty()) return;
  const int k = across[std::size_t(rng.below(int(across.size())))];
  const Vec3 p = a + rng.uniform() * (b - a);
  Vec3 q = p;
  q[k] = block_.min[k] + rng.uniform() * (block_.max[k] - block_.min[k]);
  w[seg + 1][k] = q[k];  // the far end slides across: the segment after it keeps its axis
  w.insert(w.begin() + std::ptrdiff_t(seg + 1), {p, q});
}

int MoldProblem::movable_parts(const mold::Circuit& c) const {
  if (is_blind(c.kind)) return 3;  // across the face (two) and the depth
  if (!spec_.drilling.axis_parallel) return int(c.waypoints.size());
  int n = 0;
  for (int k = 0; k < 3; ++k) for_each_aligned_run(c.waypoints, k, [&](std::size_t, std::size_t) { ++n; });
  return n;
}

int MoldProblem::move_some(mold::Circuit& c, double sigma, double probability, opt::Rng& rng) const {
  auto& w = c.waypoints;
  int moved = 0;
  if (is_blind(c.kind)) {
    // The entry's two coordinates on its face move the whole hole; the normal's, the tip alone.
    const int normal = axis_of(mold::blind_axis(pipeline_.scene(), c).face);
    for (int k = 0; k < 3; ++k) {
      if (rng.uniform() >= probability) continue;
      const double shift = sigma * rng.normal();
      if (k == normal) w.back()[k] += shift;
      else for (Vec3& p : w) p[k] += shift;
      ++moved;
    }
  } else if (spec_.drilling.axis_parallel) {
    for (int k = 0; k < 3; ++k)
      for_each_aligned_run(w, k, [&](std::size_t first, std::size_t last) {
        if (rng.uniform() >= probability) return;
        const double shift = sigma * rng.normal();
        for (std::size_t m = first; m < last; ++m) w[m][k] += shift;
        ++moved;
      });
  } else {
    for (Vec3& p : w) {
      if (rng.uniform() >= probability) continue;
      p += sigma * Vec3(rng.normal(), rng.normal(), rng.normal());
      ++moved;
    }
  }
  return moved;
}

namespace {

// Simulated binary crossover (Deb & Agrawal) of one variable, eta 10 as the benchmark problems'
// (NSGA-II's operator, which matched the ES's weighted objective on molds): one of the two
// children, near the parents' spread.
double sbx(double a, double b, opt::Rng& rng) {
  constexpr double eta = 10;
  const double u = rng.uniform();
  const double beta = u <= 0.5 ? std::pow(2 * u, 1 / (eta + 1)) : std::pow(1 / (2 * (1 - u)), 1 / (eta + 1));
  const double sign = rng.uniform() < 0.5 ? 1 : -1;
  return 0.5 * ((a + b) + sign * beta * (a - b));
}

}  // namespace

bool MoldProblem::blend_circuits(mold::Genome& a, const mold::Genome& b, opt::Rng& rng) const {
  bool blended = false;
  for (std::size_t i = 0; i < a.circuits.size() && i < b.circuits.size(); ++i) {
    auto& w = a.circuits[i].waypoints;
    const auto& v = b.circuits[i].waypoints;
    if (w.size() != v.size() || a.circuits[i].kind != b.circuits[i].kind) continue;
    if (spec_.drilling.axis_parallel) {
      // One variable per hole (aligned run) as the moves: the runs must be the same in both.
      bool same = true;
      for (int k = 0; k < 3 && same; ++k) same = aligned_runs(w, k) == aligned_runs(v, k);
      if (!same) continue;
      for (int k = 0; k < 3; ++k)
        for (const auto& [first, last] : aligned_runs(w, k)) {
          // Per variable with probability 1/2 (a's otherwise); equal values stay (cached bores).
          if (rng.uniform() >= 0.5) continue;
          const double c = sbx(w[first][k], v[first][k], rng);
          if (w[first][k] == v[first][k]) continue;
          for (std::size_t m = first; m < last; ++m) w[m][k] = c;
        }
    } else {
      for (std::size_t m = 0; m < w.size(); ++m)
        for (int k = 0; k < 3; ++k) {
          if (rng.uniform() >= 0.5) continue;
          const double c = sbx(w[m][k], v[m][k], rng);
          if (w[m][k] != v[m][k]) w[m][k] = c;
        }
    }
    repair(a.circuits[i]);  // ports on different faces blend off them: back to the nearest
    blended = true;
  }
  return blended;
}

bool MoldProblem::reach_worst(mold::Genome& g, opt::Rng& rng, long& evaluations) const {
  const mold::Scene& scene = pipeline_.scene();
  const eval::WorstSample worst = reach_->find(mold::decode(scene, g));
  if (!worst.any) return false;
  // A drill at random, then the smallest (it fits the narrowest windows).
  const auto& diameters = spec_.drilling.diameters;
  ReachRequest request{worst.point, worst.wall_distance, diameters[std::size_t(rng.below(int(diameters.size())))],
                       kReachTries, region_};
  Reached c = circuit_reaching(pipeline_, request, [this](mold::Circuit& k) { repair(k); }, rng);
  evaluations += c.evaluations;
  const double smallest = *std::min_element(diameters.begin(), diameters.end());
  if (!c.circuit && request.diameter != smallest) {
    request.diameter = smallest;
    c = circuit_reaching(pipeline_, request, [this](mold::Circuit& k) { repair(k); }, rng);
    evaluations += c.evaluations;
  }
  if (!c.circuit) return false;
  // Added, or in place of the circuit nearest the sample (which does not reach it) or of any one.
  // Only drilled circuits are counted and replaced (circuits.min and max count those).
  const auto& lim = spec_.circuits;
  const int n = int(g.circuits.size()) - count_blind(g);
  std::size_t at = g.circuits.size();
  if (n < lim.max && (n < lim.min || n == 0 || rng.uniform() < 0.5)) {
    g.circuits.push_back(*c.circuit);
  } else {
    at = nth_circuit(g, false, 0);
    if (rng.uniform() < 0.5) {
      double least = std::numeric_limits<double>::infinity();
      for (std::size_t k = 0; k < g.circuits.size(); ++k) {
        if (is_blind(g.circuits[k].kind)) continue;
        const double d = wall_distance(scene, g.circuits[k], worst.point);
        if (d < least) least = d, at = k;
      }
    } else {
      at = nth_circuit(g, false, rng.below(n));
    }
    g.circuits[at] = *c.circuit;
  }
  // Circuits the new one collides with give way, as far as circuits.min allows.
  const std::string mine = "c" + std::to_string(at) + ".";
  std::vector<std::size_t> gone;
  ++evaluations;
  for (const auto& v : pipeline_.constraints(mold::decode(scene, g)).violations) {  // bore-bore pairs only
    if (v.kind != eval::ViolationKind::BoreBore || v.elements.size() < 2) continue;
    for (int e = 0; e < 2; ++e) {
      const std::string& other = v.elements[std::size_t(1 - e)];
      if (v.elements[std::size_t(e)].rfind(mine, 0) != 0 || other.rfind(mine, 0) == 0) continue;
      const std::size_t k = std::size_t(std::stoi(other.substr(1)));
      if (std::find(gone.begin(), gone.end(), k) == gone.end()) gone.push_back(k);
    }
  }
  std::sort(gone.rbegin(), gone.rend());
  int drilled = int(g.circuits.size()) - count_blind(g);
  for (const std::size_t k : gone) {
    const bool blind = is_blind(g.circuits[k].kind);
    if (!blind && drilled <= lim.min) continue;
    g.circuits.erase(g.circuits.begin() + std::ptrdiff_t(k));
    drilled -= blind ? 0 : 1;
  }
  return true;
}

opt::Genotype MoldProblem::recombine(const opt::Genotype& a, const opt::Genotype& b, opt::Rng& rng) const {
  mold::Genome ga = genome(a);
  const mold::Genome gb = genome(b);
  if (gb.circuits.empty()) return a;
  // Coordinates blended where the parents share a circuit's shape (mutation.blend; no draw at 0:
  // runs without it are as before).
  if (rates_.blend > 0 && rng.uniform() < rates_.blend && blend_circuits(ga, gb, rng)) return encode(ga);
  // Whole-circuit crossover: a's circuits, each swapped with probability 1/2 for b's circuit
  // whose inlet is nearest.
  // A baffle swaps only with a baffle or bubbler, a drilled circuit with a drilled one: the counts stay.
  for (auto& c : ga.circuits) {
    if (rng.uniform() >= 0.5) continue;
    const mold::Circuit* nearest = nullptr;
    for (const mold::Circuit& q : gb.circuits)
      if (is_blind(q.kind) == is_blind(c.kind) &&
          (!nearest || (q.waypoints.front() - c.waypoints.front()).squaredNorm() <
                           (nearest->waypoints.front() - c.waypoints.front()).squaredNorm()))
        nearest = &q;
    if (nearest) c = *nearest;
  }
  return encode(ga);
}

opt::Score MoldProblem::evaluate(const opt::Genotype& g) const { return counted(score(pipeline_, g)); }

bool MoldProblem::skips_behind(const opt::Score& bar) const {
  return ranking_.penalty.variant == mold::PenaltyVariant::ConstrainedDomination && bar.feasible;
}

opt::Score MoldProblem::evaluate_unless_behind(const opt::Genotype& g, const opt::Score& bar) const {
  if (!skips_behind(bar)) return evaluate(g);
  return counted(score(pipeline_.evaluate_if_feasible(genome(g))));
}

opt::Score MoldProblem::counted(opt::Score s) const {
  ++evaluated_;
  if (s.feasible) ++feasible_;
  return s;
}

opt::Score MoldProblem::screen(const opt::Genotype& g) const {
  if (!screen_) return evaluate(g);
  ++screened_;
  return score(*screen_, g);
}

opt::Score MoldProblem::screen_unless_behind(const opt::Genotype& g, const opt::Score& bar) const {
  if (!screen_) return evaluate_unless_behind(g, bar);
  if (!skips_behind(bar)) return screen(g);
  ++screened_;
  return score(screen_->evaluate_if_feasible(genome(g)));
}

opt::Score MoldProblem::score(const eval::Pipeline& pipeline, const opt::Genotype& g) const {
  return score(pipeline.evaluate(genome(g)));
}

opt::Score MoldProblem::score(const eval::Evaluation& e) const {
  // "kind element element distance/margin; ..." for the run store.
  std::string detail;
  for (const auto& v : e.violations) {
    if (!detail.empty()) detail += "; ";
    detail += eval::to_string(v.kind);
    for (const auto& el : v.elements) (detail += ' ') += el;
    detail += ' ';
    append_general6(detail, v.distance);
    detail += '/';
    append_general6(detail, v.margin);
  }
  return {e.objectives, e.violation, e.feasible(), eval::scalar_fitness(e, ranking_, weights_), std::move(detail)};
}

opt::Score MoldProblem::ranking(const opt::Score& s) const {
  if (ranking_.penalty.variant == mold::PenaltyVariant::ConstrainedDomination) return s;
  const double term = eval::penalty_term(s.feasible, s.violation, ranking_.penalty);
  opt::Score r = s;
  for (std::size_t k = 0; k < r.objectives.size(); ++k)
    r.objectives[k] += term * spec_.objectives.scale(spec_.objectives.use[k]);
  r.feasible = true;
  r.violation = 0;
  return r;
}

bool MoldProblem::better(const opt::Score& a, const opt::Score& b) const {
  if (ranking_.penalty.variant == mold::PenaltyVariant::ConstrainedDomination) return opt::feasible_first(a, b);
  return a.value < b.value;
}

}  // namespace mtcs::run
