#pragma once
// A mold as an optimisation problem (DESIGN.md: Problem = Decoder + Pipeline): the genotype
// encodes circuits of waypoints, the mutations are the structural moves a bore set needs
// (shared/notes/mtcs_literature.md 7.3), the score comes from the evaluation pipeline.
//
// Genotype layout: [K, then per circuit: diameter index + 100 x kind, n, x0, y0, z0, ..., x(n-1), y, z]
// (kind 0 drilled, 1 baffle, 2 bubbler: mold::CircuitKind).
// Two forms of one layout, on purpose (docs/architecture.md, "One layout"): opt and the run store
// carry the flat opt::Genotype; the operators, the decoder and layout files work on mold::Genome.
// genome() and encode() are the one codec between them, called once on the way into and once
// on the way out of each Problem method; nothing else converts.

#include <atomic>
#include <optional>

#include "mtcs/eval/pipeline.h"
#include "mtcs/eval/worst_covered.h"
#include "mtcs/mold/genome.h"
#include "mtcs/opt/problem.h"

namespace mtcs::run {

struct MutationRates {
  double insert = 0.1, remove = 0.1, snap = 0.05, diameter = 0.05, circuit = 0.02;
  // With drilling.baffles: the probability per offspring of adding or removing a baffle or bubbler.
  double baffle = 0.05;
  // With drilling.access_map and angled holes: new and mutated circuits have their blocked bores
  // turned to free directions of the accessibility map at their entry (src/run/aim_bores.h).
  bool access_guided = true;
  // Holes (runs of aligned waypoints; waypoints for angled holes) moved per offspring on average,
  // at least one; 0: all of them, every time. Two beat all on the gear and matched them on the
  // plate at equal budgets, and keep a child's other bores cached (experiments/evaluate).
  double moves = 2;
  // Recombination (per offspring that has two parents): the probability that circuits of the
  // same shape in both parents (waypoint count and, axis-parallel, which waypoints share each
  // coordinate) get SBX-blended waypoint coordinates instead of the whole-circuit crossover.
  double blend = 0;
  // With worst_covered among the objectives: the probability per offspring of the reach move
  // instead of the others, a feasible circuit laid beside the sample the parent cools worst
  // (src/run/reach_move.h; experiments/defaults). 0: never (and no random number drawn for it).
  double reach = 0.05;
  // Axis-parallel circuits: the probability per circuit of a jog, a segment split by a new leg
  // across it (two waypoints; the segment's far end slides across with it), which turns a U into a
  // hook or a spiral in one step. Inserted waypoints are aligned with their neighbours and move
  // with them, so inserts alone rarely make one. 0: never (and no random number drawn for it).
  // Off by default: 0.2 takes the ES past ISRES on the cup but costs on the plate and the gear
  // (configs/README.md, configs/es_jog.yaml).
  double jog = 0;
};

class MoldProblem final : public opt::Problem {
 public:
  // `penalty`: the constraint-handling variant the layouts are ranked by (default: the spec's).
  // `screen`: the cheaper pipeline of a multi-fidelity run (screen() uses it), or none.
  MoldProblem(const eval::Pipeline& pipeline, std::vector<double> weights, MutationRates rates,
              std::optional<mold::PenaltyVariant> penalty = std::nullopt, const eval::Pipeline* screen = nullptr);

  std::string name() const override { return "mold"; }
  opt::Genotype sample(opt::Rng& rng) const override;
  std::size_t step_sizes(const opt::Genotype&) const override { return 1; }
  // The waypoint coordinates (the genotype minus its structure counts).
  std::size_t dimension(const opt::Genotype& g) const override;
  std::vector<double> initial_steps(const opt::Genotype&) const override { return {initial_step_}; }
  long mutate(opt::Genotype& g, const std::vector<double>& steps, opt::Rng& rng) const override;
  // The reach move only where `may_spend` covers what it can spend (kReachSpendsAtMost); else
  // the other moves, after the same draws.
  long mutate_within(opt::Genotype& g, const std::vector<double>& steps, opt::Rng& rng, long may_spend) const override;
  opt::Genotype recombine(const opt::Genotype& a, const opt::Genotype& b, opt::Rng& rng) const override;
  opt::Score evaluate(const opt::Genotype& g) const override;
  // Under constrained domination an infeasible layout ranks behind a feasible bar: its
  // objectives (the thermal stages, most of the cost) are then not computed.
  opt::Score evaluate_unless_behind(const opt::Genotype& g, const opt::Score& bar) const override;
  // The screening pipeline's score (the same as evaluate without one).
  opt::Score screen(const opt::Genotype& g) const override;
  // The screen's skip, as evaluate_unless_behind's.
  opt::Score screen_unless_behind(const opt::Genotype& g, const opt::Score& bar) const override;
  bool better(const opt::Score& a, const opt::Score& b) const override;
  // Constrained domination as it is; the penalty variants rank every layout as feasible, by each
  // objective plus the variant's penalty term (in scaled units: the same term on each).
  opt::Score ranking(const opt::Score& s) const override;

  mold::PenaltyVariant penalty_variant() const { return ranking_.penalty.variant; }

  // Layouts evaluated so far, and how many of them were feasible.
  long evaluated() const { return evaluated_; }
  long feasible_evaluated() const { return feasible_; }
  // Layouts scored by the screening pipeline only.
  long screened() const { return screened_; }

  mold::Genome genome(const opt::Genotype& g) const;
  opt::Genotype encode(const mold::Genome& genome) const;

 private:
  mold::Circuit random_circuit(opt::Rng& rng) const;
  // A baffle or bubbler of a kind drilling.baffles allows, down from one of its faces over the part.
  mold::Circuit random_blind(opt::Rng& rng) const;
  // Puts a port back on its face (nearest allowed one) and interior points inside the block.
  void repair(mold::Circuit& c) const;
  // The holes (or waypoints) of a circuit the geometric move acts on, and the move itself: each
  // shifted by sigma N(0, 1) with `probability`; returns how many moved.
  int movable_parts(const mold::Circuit& c) const;
  // The next smaller or larger of drilling.diameters, at random (mutation.diameter).
  void step_diameter(mold::Circuit& c, opt::Rng& rng) const;
  // mutation.jog on c: one segment split by a leg across it (MutationRates::jog).
  void jog(mold::Circuit& c, opt::Rng& rng) const;
  int move_some(mold::Circuit& c, double sigma, double probability, opt::Rng& rng) const;
  // mutation.blend: a's circuits blended with b's of the same index and shape; false: none had one.
  bool blend_circuits(mold::Genome& a, const mold::Genome& b, opt::Rng& rng) const;
  opt::Score score(const eval::Pipeline& pipeline, const opt::Genotype& g) const;
  opt::Score score(const eval::Evaluation& e) const;
  opt::Score counted(opt::Score s) const;  // evaluated_ and feasible_ counted
  // Whether an infeasible layout ranks behind `bar` whatever its objectives (constrained
  // domination, a feasible bar): then its thermal stages need not run.
  bool skips_behind(const opt::Score& bar) const;
  // The reach move on g: true when it laid a circuit (added, or in place of one); `evaluations`
  // grows by the pipeline evaluations it spent.
  bool reach_worst(mold::Genome& g, opt::Rng& rng, long& evaluations) const;

  const eval::Pipeline& pipeline_;
  const eval::Pipeline* screen_;
  const mold::MoldSpec& spec_;
  // The spec's objectives and penalty with this problem's variant: what the ranking reads
  // (no geometry: a variant costs no copy of the meshes).
  mold::MoldSpec ranking_;
  geometry::Box block_;
  geometry::Box region_;  // where new circuits' waypoints are drawn: around the part
  std::vector<double> weights_;
  MutationRates rates_;
  const eval::DrillAccess* access_ = nullptr;  // set: AM-guided directions
  std::optional<eval::WorstCoveredSearch> reach_;  // over the cavity samples the reach move looks at (none: off)
  double initial_step_;
  mutable std::atomic<long> evaluated_{0}, feasible_{0}, screened_{0};
};

}  // namespace mtcs::run
