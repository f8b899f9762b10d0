#include "mtcs/thermal/finite_volume.h"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

#include "thermal/fv/fv_grid.h"
#include "thermal/fv/fv_heat_input.h"

namespace mtcs::thermal {

using fv::Cut;
using fv::face_plane_axes;
using fv::kSteel;
using fv::kVoid;

namespace {

// A conductance from a steel cell to a fixed temperature (a bore wall or the air), for the
// heat balance.
struct Sink {
  int row;
  double conductance;  // W/K
  double temperature;
  int channel;  // -1 for an outer face, kPartFilm for the part's film (heat in)
};
constexpr int kPartFilm = -2;

// The heat each steel cell takes from the cavity over the area of its faces to it (W/mm^2),
// for extrapolating samples to the cavity wall.
void record_wall_flux(const fv::Grid& grid, const std::vector<double>& source, FvField& field) {
  for (int kk = 0; kk < field.cells[2]; ++kk)
    for (int j = 0; j < field.cells[1]; ++j)
      for (int i = 0; i < field.cells[0]; ++i) {
        const std::size_t cell = field.index(i, j, kk);
        if (source[cell] == 0) continue;
        double open = 0;  // area of the faces to the cavity
        for (int dir = 0; dir < 6; ++dir) {
          std::array<int, 3> nb{i, j, kk};
          nb[dir / 2] += dir % 2 ? 1 : -1;
          if (grid.inside(nb[0], nb[1], nb[2]) && grid.kind(nb[0], nb[1], nb[2]) == kVoid)
            open += field.spacing[(dir / 2 + 1) % 3] * field.spacing[(dir / 2 + 2) % 3];
        }
        if (open > 0) field.wall_flux[cell] = source[cell] / open;
      }
}

// The linear system: one row per steel cell; the conductances to the bore walls and the air
// are kept for the heat balance.
struct System {
  std::vector<int> row;  // per cell, -1 when not steel
  Eigen::SparseMatrix<double> matrix;
  Eigen::VectorXd heat;  // W per row from heat_in; the sinks' g T terms stay in `sinks`
  std::vector<Sink> sinks;
};

System assemble(const Model& model, const fv::Grid& grid, const FvField& field, const std::vector<double>& source,
                const std::vector<fv::PartFilm>& films) {
  const Setting& setting = model.setting;
  const double k = setting.conductivity;
  const std::size_t n_cells = source.size();
  System system;
  std::vector<int>& row = system.row;
  Eigen::VectorXd& heat = system.heat;
  std::vector<Sink>& sinks = system.sinks;
  row.assign(n_cells, -1);
  // Number the steel cells.
  int n = 0;
  for (int kk = 0; kk < field.cells[2]; ++kk)
    for (int j = 0; j < field.cells[1]; ++j)
      for (int i = 0; i < field.cells[0]; ++i)
        if (grid.kind(i, j, kk) == kSteel) row[field.index(i, j, kk)] = n++;
  if (n == 0) throw std::invalid_argument("finite volume: no steel cell (the cell size is too coarse?)");

  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(std::size_t(n) * 7);
  heat = Eigen::VectorXd::Zero(n);
  // The part's films: diagonal entries, kept as sinks (their heat flows the other way).
  std::vector<double> film_diagonal(std::size_t(n), 0.0);
  for (const fv::PartFilm& f : films) {
    const int r = row[f.cell];
    if (r < 0) throw std::logic_error("finite volume: a part film on a cell that is not steel");
    film_diagonal[std::size_t(r)] += f.conductance;
    sinks.push_back({r, f.conductance, f.temperature, kPartFilm});
  }
  for (int kk = 0; kk < field.cells[2]; ++kk)
    for (int j = 0; j < field.cells[1]; ++j)
      for (int i = 0; i < field.cells[0]; ++i) {
        const std::size_t cell = field.index(i, j, kk);
        const int r = row[cell];
        if (r < 0) continue;
        const std::array<int, 3> ijk{i, j, kk};
        double diagonal = film_diagonal[std::size_t(r)];
        heat[r] += source[cell];
        for (int dir = 0; dir < 6; ++dir) {
          const int a = dir / 2, step = dir % 2 ? 1 : -1;
          const double area = field.spacing[(a + 1) % 3] * field.spacing[(a + 2) % 3];
          const double h = field.spacing[a];
          std::array<int, 3> nb = ijk;
          nb[a] += step;
          const bool boundary = !grid.inside(nb[0], nb[1], nb[2]);
          const Cut* cut = grid.cut(cell, dir);
          Cut fallback{};
          if (!cut && !boundary &&
              grid.kind(nb[0], nb[1], nb[2]) >= 0) {  // rounding: the centre is in, no entry found
            fallback = Cut{h, 1.0, grid.kind(nb[0], nb[1], nb[2])};
            cut = &fallback;
          }
          if (boundary) {  // the heat entering there, even where a bore cuts the link
            const auto [ab, ac] = face_plane_axes(dir);
            heat[r] += field.face_heat[std::size_t(dir)][std::size_t(ijk[ab]) +
                                                         std::size_t(field.cells[ab]) * std::size_t(ijk[ac])];
          }
          if (cut) {
            const Channel& ch = model.channels[std::size_t(cut->channel)];
            // Conduction to the wall in series with the film; a tiny distance is floored so the
            // row stays finite (the cell then sits at the wall's temperature).
            const double distance = std::max(cut->t, 1e-9 * h);
            const double film = std::isinf(ch.film) ? 0.0
                                : cut->cosine > 0   ? 1 / (ch.film * cut->cosine)
                                                    : -1;
            const double g = film < 0 ? 0.0 : area / (distance / k + film);
            diagonal += g;
            sinks.push_back({r, g, ch.coolant, cut->channel});
          } else if (boundary) {
            const auto [ab, ac] = face_plane_axes(dir);
            const std::size_t f = std::size_t(ijk[ab]) + std::size_t(field.cells[ab]) * std::size_t(ijk[ac]);
            const FaceCondition& fc = setting.faces[std::size_t(dir)];
            const double open = std::max(0.0, area - field.face_covered[std::size_t(dir)][f]);
            const double g = fc.film > 0 ? open / (0.5 * h / k + 1 / fc.film) : 0.0;
            diagonal += g;
            if (g > 0) sinks.push_back({r, g, fc.ambient, -1});
          } else if (grid.kind(nb[0], nb[1], nb[2]) == kSteel) {
            const double g = k * area / h;
            diagonal += g;
            entries.emplace_back(r, row[field.index(nb[0], nb[1], nb[2])], -g);
          }  // a void neighbour: adiabatic
        }
        entries.emplace_back(r, r, diagonal);
      }
  system.matrix.resize(n, n);
  system.matrix.setFromTriplets(entries.begin(), entries.end());
  return system;
}

}  // namespace

namespace {

// The finite volumes of one model, built once: the grid, the heat input, the matrix and its
// preconditioner. Solved for any coolant temperatures of the channels: the coolant's warming
// along its circuits (a fixed point of a few solves) changes nothing else.
class Assembled {
 public:
  Assembled(const Model& model, const FvOptions& options)
      : model_(model), options_(options), grid_(model, options, field_), source_(prepare(field_, model.setting)),
        heat_(model, grid_, field_, source_) {
    system_ = assemble(model, grid_, field_, source_, heat_.films());
    const auto start = std::chrono::steady_clock::now();
    if (options.preconditioner == FvPreconditioner::IncompleteCholesky) compute(ic_);
    else compute(diagonal_);
    preconditioner_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  // coolant: each channel's (degrees C), in model.channels' order.
  FvResult solve(const std::vector<double>& coolant, const Samples& samples) const {
    FvResult result;
    result.field = field_;
    FvField& field = result.field;
    std::vector<double> source = source_;
    std::vector<Sink> sinks = system_.sinks;
    for (Sink& s : sinks)
      if (s.channel >= 0) s.temperature = coolant[std::size_t(s.channel)];
    const std::vector<int>& row = system_.row;
    const int n = int(system_.heat.size());

    // A cell whose centre is a hair from a bore wall has a conductance to it many orders above
    // the others. Measured against the raw right-hand side, which such rows dominate, the CG
    // tolerance would mean nothing for the rest; and the heat through such a link is a tiny
    // temperature difference times a huge conductance, lost if T is rounded near 40 degrees.
    // So each cell with sinks starts at its dominant sink's temperature `base` plus `offset`
    // (the conductance-weighted pull of the others); we solve for the correction to that guess,
    // whose right-hand side is of the scale of the ordinary rows, and keep T - base unrounded.
    Eigen::VectorXd base = Eigen::VectorXd::Zero(n), offset = Eigen::VectorXd::Zero(n);
    {
      Eigen::VectorXd strongest = Eigen::VectorXd::Zero(n), total = Eigen::VectorXd::Zero(n);
      double sum = 0, weight = 0;
      for (const Sink& s : sinks) {
        if (s.conductance > strongest[s.row]) strongest[s.row] = s.conductance, base[s.row] = s.temperature;
        sum += s.conductance * s.temperature, weight += s.conductance;
      }
      const double mean = weight > 0 ? sum / weight : 0.0;
      for (int r = 0; r < n; ++r)
        if (strongest[r] == 0) base[r] = mean;
      for (const Sink& s : sinks) {
        offset[s.row] += s.conductance * (s.temperature - base[s.row]);
        total[s.row] += s.conductance;
      }
      for (int r = 0; r < n; ++r)
        if (total[r] > 0) offset[r] /= total[r];
    }
    // The guess's residual, each term a difference of nearby temperatures (no g T - g T).
    Eigen::VectorXd residual = system_.heat;
    for (const Sink& s : sinks) residual[s.row] += s.conductance * ((s.temperature - base[s.row]) - offset[s.row]);
    for (int col = 0; col < n; ++col)
      for (Eigen::SparseMatrix<double>::InnerIterator it(system_.matrix, col); it; ++it)
        if (it.row() != col)
          residual[it.row()] += it.value() * ((base[it.row()] - base[col]) + (offset[it.row()] - offset[col]));
    if (options_.preconditioner == FvPreconditioner::IncompleteCholesky) offset += iterate(*ic_, residual, result);
    else offset += iterate(*diagonal_, residual, result);
    result.steel_cells = std::size_t(n);

    const std::size_t n_cells = source.size();
    field.kind.resize(n_cells);
    field.temperature.assign(n_cells, fv::kNoTemperature);
    for (int kk = 0; kk < field.cells[2]; ++kk)
      for (int j = 0; j < field.cells[1]; ++j)
        for (int i = 0; i < field.cells[0]; ++i) {
          const std::size_t cell = field.index(i, j, kk);
          const int kind = grid_.kind(i, j, kk);
          field.kind[cell] = kind;
          if (kind == kSteel)
            field.temperature[cell] = base[row[cell]] + offset[row[cell]];
          else if (kind >= 0)
            field.temperature[cell] = coolant[std::size_t(kind)];
        }

    result.heat_in = heat_.total();
    result.heat_to_channel.assign(model_.channels.size(), 0.0);
    for (const Sink& s : sinks) {
      const double q = s.conductance * ((base[s.row] - s.temperature) + offset[s.row]);
      if (s.channel >= 0)
        result.heat_to_channel[std::size_t(s.channel)] += q;
      else if (s.channel == -1)
        result.heat_to_faces += q;
    }
    // What the part's films let in, where the samples' extrapolation to the wall reads it: the
    // patches' face cells, the cavity's cells.
    for (const fv::PartFilm& f : heat_.films()) {
      const double q = f.conductance * (f.temperature - field.temperature[f.cell]);
      result.heat_in += q;
      if (f.face >= 0)
        field.face_heat[std::size_t(f.face)][f.face_cell] += q;
      else
        source[f.cell] += q;
    }
    record_wall_flux(grid_, source, field);
    for (double q : result.heat_to_channel) result.heat_to_channels += q;

    result.temperature.reserve(samples.size());
    for (const Vec3& p : samples.points) result.temperature.push_back(field.temperature_at(p));
    return result;
  }

 private:
  template <class Preconditioner>
  using Cg = Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper, Preconditioner>;
  using IcCg = Cg<Eigen::IncompleteCholesky<double, Eigen::Lower, Eigen::NaturalOrdering<int>>>;
  using DiagonalCg = Cg<Eigen::DiagonalPreconditioner<double>>;

  // The field's conductivity and faces, each face's heat and covered area sized (the heat input
  // fills them); the source per cell, zero. After the grid has set the cells.
  static std::vector<double> prepare(FvField& field, const Setting& setting) {
    field.conductivity = setting.conductivity;
    field.faces = setting.faces;
    for (int face = 0; face < 6; ++face) {
      if (!(setting.faces[std::size_t(face)].film >= 0) || !std::isfinite(setting.faces[std::size_t(face)].film) ||
          !std::isfinite(setting.faces[std::size_t(face)].ambient))
        throw std::invalid_argument("finite volume: face films must be finite and >= 0");
      const auto [ab, ac] = face_plane_axes(face);
      field.face_heat[std::size_t(face)].assign(std::size_t(field.cells[ab]) * std::size_t(field.cells[ac]), 0.0);
      field.face_covered[std::size_t(face)] = field.face_heat[std::size_t(face)];
    }
    return std::vector<double>(std::size_t(field.cells[0]) * std::size_t(field.cells[1]) * std::size_t(field.cells[2]), 0.0);
  }

  template <class Solver>
  void compute(std::unique_ptr<Solver>& solver) {
    solver = std::make_unique<Solver>();
    solver->setTolerance(options_.tolerance);
    solver->setMaxIterations(options_.max_iterations);
    solver->compute(system_.matrix);
    if (solver->info() != Eigen::Success) throw std::runtime_error("finite volume: the preconditioner failed");
  }

  template <class Solver>
  Eigen::VectorXd iterate(const Solver& solver, const Eigen::VectorXd& rhs, FvResult& result) const {
    const auto start = std::chrono::steady_clock::now();
    Eigen::VectorXd x = solver.solve(rhs);
    result.iterations = int(solver.iterations());
    result.residual = solver.error();
    result.converged = solver.info() == Eigen::Success;
    result.solver_seconds = preconditioner_seconds_ +
                            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return x;
  }

  const Model& model_;
  FvOptions options_;
  FvField field_;  // the grid's cells, the faces' heat: filled by grid_ and heat_
  fv::Grid grid_;
  std::vector<double> source_;  // W per cell from the fixed flux, before the part's films
  fv::HeatInput heat_;
  System system_;
  std::unique_ptr<IcCg> ic_;
  std::unique_ptr<DiagonalCg> diagonal_;
  double preconditioner_seconds_ = 0;
};

std::vector<double> coolants_of(const Model& model) {
  std::vector<double> out;
  for (const Channel& c : model.channels) out.push_back(c.coolant);
  return out;
}

}  // namespace

// Each bore's coolant at its mean along the bore: the inlet's plus, over the circuit's capacity
// rate, the heat of the bores upstream and half its own. The heat depends on the coolant only
// weakly (the rise is a small share of the wall's drive): a fixed point, each step shrinking the
// change by about that share (a few % at 2-8 l/min), so two or three solves bring the last step
// under kTolerance. One that does not settle in kMaxSolves is reported as not converged.
FvResult solve_finite_volume(const Model& model, const Samples& samples, const FvOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const Assembled assembled(model, options);
  std::vector<double> coolant = coolants_of(model);
  const bool warms = std::any_of(model.channels.begin(), model.channels.end(),
                                 [](const Channel& c) { return c.circuit >= 0 && c.capacity > 0; });
  constexpr double kTolerance = 0.02;  // K, the largest change of a bore's coolant in the last step
  constexpr int kMaxSolves = 8;
  FvResult result;
  for (int solve = 1;; ++solve) {
    result = assembled.solve(coolant, samples);
    result.coolant_solves = solve;
    if (!warms) break;
    double change = 0;
    for (std::size_t c = 0; c < model.channels.size(); ++c) {
      const Channel& ch = model.channels[c];
      if (ch.circuit < 0 || !(ch.capacity > 0)) continue;
      double upstream = result.heat_to_channel[c] / 2;
      for (std::size_t d = 0; d < model.channels.size(); ++d)
        if (d != c && model.channels[d].circuit == ch.circuit && model.channels[d].position < ch.position)
          upstream += result.heat_to_channel[d];
      const double next = ch.coolant + upstream / ch.capacity;
      change = std::max(change, std::abs(next - coolant[c]));
      coolant[c] = next;
    }
    if (change <= kTolerance) break;
    if (solve == kMaxSolves) {
      result.converged = false;
      break;
    }
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace mtcs::thermal
