#pragma once
// The cavity void for the line-sink tiers, any cavity mesh (thermal.cavity_void: surface).
// The line sinks and the heat input's sheets live in solid steel; the part's void (plastic,
// which barely conducts) is not steel, and its wall takes no heat but the cavity's own. On a
// thin shell (a cup) that is the whole story: without the void, the bores outside cool the
// core through 2.5 mm of "steel"; the line sinks read the finite volumes with Kendall tau 0.18
// and an RMS error of 47 K there, with the void filled in the finite volumes as well tau 0.91
// and 2 K (experiments/thermal/void_surface.md).
//
// So each source field f gets a correction: a single layer tau on the wall whose steel-side
// normal derivative cancels f's, (1/2 - K') tau = df/dn (n into the steel, K' the adjoint
// double layer, the block's images included), on panels of constant tau about `panel` mm wide
// (the wall's triangles cut finer, gathered per cell of a grid whose planes hold the faces of
// walls thinner than a panel, so that a thin shell's two faces pair, and per direction of the
// normal). Near panels are integrated exactly (closed forms per sub-triangle), far ones as
// points; between near panels the condition holds for the flux through the panel, not at one
// point (across a thin void the two faces see each other at nearly a half space: only the flux
// keeps the small difference that matters), graded toward an edge where two panels meet (the
// flux is singular there). The heat input's own correction joins its sheets (their fluxes
// change, nothing else does); a channel's columns get the layer answering their normal
// derivatives at the panels, at the samples, the faces and every channel's wall. Left out:
// the face losses' reflection at the channels' walls (the faces take a few % of the heat).
// Private to src/thermal.

#include <Eigen/Dense>
#include <array>
#include <functional>
#include <span>
#include <vector>

#include "thermal/cavity/panel_matrix_cache.h"
#include "thermal/kernels/line_sink_fields.h"
#include "mtcs/thermal/model.h"

namespace mtcs::thermal {

// The far lattice of the images not summed exactly: a charge and first moment about `center`
// (4 numbers) times kernel(p) is their field at p (LineSinkModel::Impl::far_kernel).
struct FarLattice {
  std::function<Eigen::Vector4d(const Vec3&)> kernel;
  Vec3 center = Vec3::Zero();
};

class VoidSurface {
 public:
  // wall: the cavity's triangles as in Setting::heat_in (counter-clockwise from the void),
  // with their fluxes and films; images: the reflections summed exactly. Throws
  // std::invalid_argument on a panel size <= 0 or a wall without area.
  //
  // A wall with a film (the part's coupling, HeatedTriangle::film) takes heat h (T_p - T) on
  // top of its flux: a layer whose temperature at the panels is T_L = P tau + F L tau (P the
  // panels' potentials at their points, L tau its charge and first moment, F their far
  // lattice at the points) answers d - H f with (A + H P + H F L) tau = d - H f, H = film / k
  // per panel, f the field's temperature at the points (docs/thermal-model.md, "The coupled
  // cavity in the line sinks"). `far` gives F; without a film it is not used.
  //
  // A wall on a block face (a patch: the melt outside the block) is no void: the face's image
  // already keeps every source's flux there, so A = I (the layer is the film's extra flux / k)
  // and d = 0 for every source.
  VoidSurface(std::span<const HeatedTriangle> wall, std::span<const Image> images, double panel,
              double conductivity, const FarLattice& far = {}, bool on_block_face = false);
  bool on_block_face() const { return on_block_face_; }

  // Whether a film acts on the wall: then solve and layer answer the Robin condition.
  bool robin() const { return robin_; }
  // Per panel: film / k (1/mm), the part's temperature (degrees C, where the film acts).
  const Eigen::VectorXd& film_over_k() const { return film_over_k_; }
  const Eigen::VectorXd& part_temperatures() const { return part_; }
  // 4 x panels: a layer's charge (W, heat into the steel) and its first moment about the far
  // lattice's centre, per unit tau.
  const Eigen::MatrixXd& moments() const { return moments_; }

  std::size_t panels() const { return point_.size(); }
  // The panels' width: `panel`, or wider on a wall too large for 3000 panels of that width.
  double panel() const { return panel_; }
  // Each panel's collocation point (on the wall) and normal into the steel.
  const std::vector<Vec3>& points() const { return point_; }
  const std::vector<Vec3>& normals() const { return normal_; }

  // The heat input's own correction, a source like any other: its sheets (q / k per panel)
  // seen from the void's side, (1/2 + K') q / k, stand for its normal derivative D (the heat
  // the model without the void sends into it, sent back into the steel); and its layer, on a
  // wall with a film without the film's answer to the sheets' field (the caller adds it).
  const Eigen::VectorXd& heat_derivatives() const { return heat_d_; }
  const Eigen::VectorXd& heat_layer() const { return heat_tau_; }

  // targets x panels: the temperature at each target of the layer solving (1/2 - K') tau = d
  // for a unit d at each panel, (1/4 pi) S A^-1. A field whose steel-side normal derivative at
  // the panels is D (panels x columns) gets response D added at the targets.
  Eigen::MatrixXd response(std::span<const Vec3> targets) const;
  // R A^-1 for rows R (x panels) by the LU, in double: the response of averages of targets
  // (R = their weights times potentials) without one solve per target.
  Eigen::MatrixXd times_inverse(const Eigen::MatrixXd& r) const;
  // A^-1 D in double, by the LU (no columns: none; Eigen's solve would touch the empty D's data).
  Eigen::MatrixXd solve(const Eigen::MatrixXd& d) const {
    return d.cols() == 0 ? Eigen::MatrixXd(d.rows(), 0) : Eigen::MatrixXd(lu_.solve(d));
  }
  // The layer tau = A^-1 D of normal derivatives D (panels x columns), in single precision by
  // A^-1 kept explicit (a product, not two triangular solves), and its temperature at targets:
  // potentials(targets) tau, potentials (targets x panels) = (1/4 pi) S.
  Eigen::MatrixXf layer(const Eigen::MatrixXf& d) const;
  Eigen::MatrixXd potentials(std::span<const Vec3> targets) const;
  // potentials(targets), kept by the panels and the targets (panel_matrix_cache.h): for the
  // fixed targets a model builds again at each film (its samples, the faces' points), in memory;
  // at the panels' own points (nearly all pairs near, as costly as the panel matrix) on disk too.
  std::shared_ptr<const Eigen::MatrixXd> kept_potentials(std::span<const Vec3> targets, Keep keep = Keep::memory) const;

  // Whether the cylinder of `radius` about a -> b reaches the wall (a bore through the part, or
  // touching it: an illegal layout, whose columns keep no reflection, as without the void).
  bool reaches(const Vec3& a, const Vec3& b, double radius) const;

 private:
  struct Sub {
    TriangleSource source;
    Vec3 centroid;
    double area, flux, film, part;
  };
  // A = 1/2 - K' into A (panels x panels), rows in parallel.
  void assemble(Eigen::MatrixXd& A) const;
  // Every input of the panels' matrices (their width and grouping, the sub-triangles' corners,
  // the far pass's origin and the images), as their digest.
  void add_panels(io::CacheKey& key) const;
  // potentials(targets) into S, sized targets x panels.
  void fill_potentials(std::span<const Vec3> targets, Eigen::MatrixXd& S) const;
  // The gradient's component along `normal` of panel j's unit layer at p, images summed, free
  // of 1/(4 pi) (the potential: potential_row).
  double panel_gradient(std::size_t j, const Vec3& p, const Vec3& normal) const;
  // 1 / (4 pi) times the potential of every panel's unit layer at x, images summed, into row
  // (panels): the far panels by their second moments (one float pass over all panels per
  // image, AVX2 when the CPU has it), the near ones by their sub-triangles in double.
  void potential_row(const Vec3& x, double* row) const;
  // How far x lies from panel j's sub-triangles (each as a ball about its centroid; 0 inside).
  double distance_to_panel(std::size_t j, const Vec3& x) const;
  // The flux of panel j's unit layer (free of 1/(4 pi), images summed) through triangle abc
  // along `steel`, the triangle halved while wider than its distance to panel j, down to
  // kGradedDepth levels (`depth`: this call's).
  double graded_flux(std::size_t j, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& steel, int depth) const;
  // Panel j's sub-triangles at p (one image): exactly within kNearSub of their size, else as points.
  double near_potential(std::size_t j, const Vec3& p) const;

  std::vector<Image> images_;
  double conductivity_ = 0, panel_ = 0;
  std::vector<Sub> sub_;                       // by panel
  std::vector<std::size_t> begin_{0};          // panel j: sub_[begin_[j], begin_[j + 1])
  std::vector<Vec3> point_, normal_, centroid_;
  std::vector<double> area_, radius_, flux_;   // flux: area-weighted mean over the panel
  std::vector<double> corner_reach_;           // the farthest sub-triangle corner from the centroid
  // By column and in float, for potential_row's pass: centroids (from the wall's lowest corner
  // `origin`), areas, the squared distance from which a panel is far, and the six entries and
  // trace of its second moment, the sum of area (c - centroid)(c - centroid)^T over its subs.
  struct FarTerms {
    Vec3 origin = Vec3::Zero();
    std::vector<float> cx, cy, cz, area, far2, xx, yy, zz, xy, xz, yz, trace;
  } far_;
  std::array<unsigned char, 16> panels_digest_{};  // add_panels
  bool robin_ = false, on_block_face_ = false;
  Eigen::VectorXd film_over_k_, part_;
  Eigen::MatrixXd moments_;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;   // of A = 1/2 - K' (with a film, A + H P + H F L)
  Eigen::MatrixXf inverse_transposed_;         // A^-T: A^-1 by rows (skinny_product.h)
  Eigen::VectorXd heat_d_, heat_tau_;          // the heat input's own correction
};

}  // namespace mtcs::thermal
