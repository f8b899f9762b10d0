#pragma once
// The line-sink model's insides, shared by its files: the cached per-channel blocks, the
// convective faces, and Impl (what LineSinkModel precomputes per setting and samples).
//   line_sink_setup.cpp    the model's build: images, faces, samples, tabulated fields
//   line_sink_channel.cpp  one channel's influence columns (what the cache keeps)
//   line_sinks.cpp         one layout: cache lookup, assembly, dense solve, sample sums

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include "thermal/kernels/heat_source_tree.h"
#include "thermal/kernels/line_sink_fields.h"
#include "thermal/line_sinks/line_sink_tables.h"
#include "thermal/cavity/void_surface.h"
#include "mtcs/thermal/line_sinks.h"

namespace mtcs::thermal {

using Eigen::MatrixXd;
using Eigen::VectorXd;

inline constexpr double kInfiniteFilm = std::numeric_limits<double>::infinity();

// ---- cache blocks ----------------------------------------------------------------------------

struct LineSinkCache::ChannelBlock {
  ChannelAxis axis;
  PointSet walls;  // 4 wall points per element, all images, relative to walls_origin
  Vec3 walls_origin = Vec3::Zero();
  bool walls_single = false;  // the radius is coarse enough for the float kernel
  int cols = 0;
  std::vector<float> sample_cols_f;   // samples x cols, column-major (single precision)
  std::vector<double> sample_cols_d;  // the same in double precision
  MatrixXd face_means;                // convective faces x cols
  MatrixXd self;                      // rows x cols: own columns at own rows (V_self removed)
  std::vector<double> self_dipole;    // per row: the own element's dipole at its own wall
  VectorXd heat_rows;                 // heat input's field at the rows
  MatrixXd face_rows;                 // rows x convective faces
  MatrixXd far_rows;                  // rows x 4: the far lattice's kernel (see Impl::far_kernel)
  MatrixXd moments;                   // 4 x cols: each column's charge and first moment
  // The part's void (Impl::void_surface), in float as the layer: the layer answering the
  // columns (panels x cols; empty for a bore reaching the void), and the panels' potentials at
  // the rows (panels x rows: transposed, for skinny_product.h).
  Eigen::MatrixXf void_tau, void_rows;
  // A coupled cavity (Impl::robin): the layer's charge and first moment (4 x cols), the far
  // lattice of a layer at the rows (rows x 4, the void's far images), and the layers of the
  // free constant, the face losses and the fixed sources at the rows.
  MatrixXd layer_moments, far_rows_layer, face_layer_rows;
  VectorXd t0_rows;
};

struct LineSinkCache::PairBlock {
  MatrixXd block;  // rows of the first channel x columns of the second
};

// ---- the model -------------------------------------------------------------------------------

struct ConvectiveFace {
  int face = 0;
  double film = 0, ambient = 0;
  double area = 0, convective_area = 0;
  std::array<Vec3, 4> corners;
  std::array<TriangleSource, 2> halves;  // corners 0 1 2 and 0 2 3
  std::vector<Vec3> cool;           // the grid points off the heated triangles
  Vec3 center;
};

struct LineSinkModel::Impl {
  Setting setting;
  LineSinkOptions options;
  int kinds = 1;  // columns per element: 1 (sink) or 3 (sink, two dipoles)
  double inv4pik = 0;
  double tol = 0;
  std::vector<Image> images;      // summed exactly
  std::vector<Image> far_images;  // summed as the charge and dipole of the whole block's image
  Vec3 center = Vec3::Zero();     // the block's centre: where the moments are taken
  Vec3 sample_origin = Vec3::Zero();  // the samples' centre: their float coordinates' origin
  Eigen::Vector4d heat_moments = Eigen::Vector4d::Zero();
  Eigen::Matrix<double, 4, Eigen::Dynamic> face_moments;  // per convective face (column)
  MatrixXd far_samples;       // samples x 4: the far lattice for the channels' columns
  MatrixXd far_samples_fixed; // the same for the heat input and the faces (exact to `images`)
  MatrixXd far_face_means;                   // faces x 4: the far lattice for the channels
  MatrixXd far_face_means_fixed;             // the same for the heat input and the faces
  FieldGrid face_grid;
  // The heat input's field on a grid over the block, and on a finer one around the heated
  // triangles (large blocks only: `heat_fine_box`); for collocation points in `heat_near` (the
  // triangles' bounds grown by two cells of the finest grid there) it is summed exactly.
  // Two fields per node: the whole heat input, and the part of its `far_heat_images` alone.
  // In heat_near only the near images' triangles are summed exactly (the identity and images
  // whose triangles lie close: one or two of ~25); the far ones, smooth there, are interpolated.
  FieldGrid heat_grid, heat_fine;
  Box heat_fine_box = Box::empty();
  Box heat_near = Box::empty();
  std::vector<Image> near_heat_images, far_heat_images;

  // The far lattice's kernel on the same grid: its images of the centre lie a block's width or
  // more outside, so it is smooth everywhere inside.
  FieldGrid far_grid;
  Eigen::Vector4d far_at(const Vec3& p) const {
    if (far_grid.values.empty() || !setting.block.contains(p)) return far_kernel(p);
    Eigen::Vector4d v;
    far_grid.interpolate(p, v.data());
    return v;
  }

  double heat_at(const Vec3& p) const {
    if (heat_grid.values.empty() || !setting.block.contains(p)) return heat_field(p);
    double v[2];
    (heat_fine_box.contains(p) ? heat_fine : heat_grid).interpolate(p, v);
    if (!heat_near.contains(p)) return v[0];
    return heat_field(p, near_heat_images) + v[1];
  }
  std::vector<ConvectiveFace> faces;
  std::optional<double> fixed_constant;  // an isothermal face's ambient
  double heat_in = 0;
  std::size_t n_samples = 0;
  PointSet sample_set;                       // the samples, image-expanded
  PointSet face_set;                         // the convective faces' grid points, one target each
  MatrixXd face_average;                     // faces x grid points: each face's mean
  VectorXd heat_samples;                     // heat input's field at the samples
  MatrixXd face_samples;                     // samples x faces: unit face loss
  VectorXd heat_face_means;                  // per face: heat input's field, face mean
  MatrixXd face_face_means;                  // faces x faces

  // The part's void (options.void_panel): the panels' potentials at the samples (a layer's
  // field there is these times the layer), and the response of the faces' means to a field's
  // normal derivative at the panels, which the panels' points +- void_step along their normals
  // give by central differences. The samples keep potentials, not their response S A^-1: that
  // costs a solve per sample (34 600 of them for a field on the gear), a layer one per column.
  std::shared_ptr<const VoidSurface> void_surface;  // shared by the models of one setting
  std::shared_ptr<const MatrixXd> void_potentials;  // samples x panels (kept: VoidSurface::kept_potentials)
  Eigen::MatrixXf void_potentials_ft;  // its transpose in float, for the float columns (skinny_product.h)
  MatrixXd void_faces;            // convective faces x panels
  MatrixXd face_void;             // faces x faces: the face losses' correction at the faces
  PointSet void_pairs;  // per panel, its point + void_step n and - void_step n (one chunk)
  double void_step = 0;
  // The normal derivatives at the panels of `source`'s columns (panels x cols), by the float
  // kernel: relative error ~1e-4 at a step of 1 % of the panel.
  Eigen::MatrixXf void_derivatives(const ChannelAxis& source) const;
  // With a film: d - H f for the columns (f their temperature at the panels' points, the mean
  // of the two points of each pair, plus their far lattice by `moments`, the columns' own).
  Eigen::MatrixXf void_robin_rhs(const ChannelAxis& source, const MatrixXd& moments) const;

  // A coupled cavity (void_surface.h: a wall with a film). Each source's layer answers the
  // film too, so the layers carry heat: their charge and first moment join the far lattice
  // (with the void's far images, `sample_far`) and the energy balance. Per source: the
  // free constant (t0_*: its field is 1 plus its layer's), the face losses (face_tau), the fixed
  // sources (heat_tau: the sheets and the part's temperature).
  bool robin = false;
  std::vector<Image> sample_far;
  MatrixXd void_face_potentials;  // convective faces x panels: the faces' means of the potentials
  MatrixXd far_panels;            // panels x 4: the far lattice (sample_far) at the panels' points
  VectorXd heat_tau;              // the fixed sources' layer (also without a film: the heat's)
  Eigen::Vector4d heat_layer_moments = Eigen::Vector4d::Zero();
  VectorXd t0_tau, t0_samples, t0_face_means;
  Eigen::Vector4d t0_moments = Eigen::Vector4d::Zero();
  MatrixXd face_tau, face_layer_moments;  // panels x faces, 4 x faces
  // The above, once the void, the faces, the samples and their far lattices are built; `d`: the
  // face losses' normal derivatives at the panels (panels x faces), `at_faces`: the panels'
  // potentials at the faces' grid points (points x panels).
  void build_robin_fields(const MatrixXd& at_faces, const MatrixXd& d);

  // The heated triangles with a flux (a region without flux, molds/plate.yaml's top face and
  // rim, adds +-0 to the sum: left out, the same bits at half the potentials on the plate).
  struct HeatSource {
    TriangleSource triangle;
    double flux = 0;  // W/mm^2
  };
  std::vector<HeatSource> heat_sources;
  // Many heated triangles (a mesh cavity): their sum by a tree (heat_source_tree.h), per image
  // at the image of p. A few (a box cavity, a patch): the direct sum, as before the tree.
  static constexpr std::size_t kTreeAbove = 16;
  std::optional<HeatSourceTree> heat_tree;
  double heat_field(const Vec3& p) const { return heat_field(p, images); }
  double heat_field(const Vec3& p, std::span<const Image> of) const {
    double sum = 0;
    if (heat_tree) {
      for (const Image& g : of) sum += g.sign * heat_tree->potential(g.mult.cwiseProduct(p) + g.offset);
    } else {
      for (const HeatSource& h : heat_sources) sum += h.flux * triangle_image_potential(of, h.triangle, p);
    }
    return sum * inv4pik;
  }
  // Field of a unit uniform loss (W/mm^2 out of the steel) over a face.
  double face_field(const ConvectiveFace& f, const Vec3& p) const {
    return -inv4pik * (triangle_image_potential(images, f.halves[0], p) +
                       triangle_image_potential(images, f.halves[1], p));
  }


  // Adds w * (columns of `axis` at p) to col[0 .. elements * kinds).
  void add_columns(const ChannelAxis& axis, const Vec3& p, double w, double* col) const {
    double phi[64], d1[64], d2[64];
    const int m = axis.elements;
    element_fields(axis, p, phi, kinds == 3 ? d1 : nullptr, d2);
    const double s = w * inv4pik;
    for (int e = 0; e < m; ++e) {
      col[e * kinds] -= s * phi[e];  // a sink: q' W/mm leaves the steel
      if (kinds == 3) {
        col[e * kinds + 1] += s * d1[e];
        col[e * kinds + 2] += s * d2[e];
      }
    }
  }

  // The far lattice's kernel over 4 pi k (line_sink_fields.h): dotted with the charge and first
  // moment (about `center`) of everything in the block, the far images' field.
  Eigen::Vector4d far_kernel(const Vec3& s) const { return far_kernel(s, far_images); }
  Eigen::Vector4d far_kernel(const Vec3& s, std::span<const Image> far) const {
    return far_lattice_kernel(far, center, s) * inv4pik;
  }

  // The wall points of element e: m +- R n1, m +- R n2.
  std::array<Vec3, 4> wall_points(const ChannelAxis& a, int e) const {
    const Vec3 m = a.p0 + ((e + 0.5) * a.element_length) * a.u;
    return {m + a.radius * a.n1, m - a.radius * a.n1, m + a.radius * a.n2, m - a.radius * a.n2};
  }

  // The rows' functionals of any field f (images included by f): per element the wall's
  // four-point mean and, for T2d, the half-differences along n1 and n2 (first harmonic).
  template <class Field>
  void row_functionals(const ChannelAxis& rows, Field&& f, int width, double* out, int stride) const {
    std::vector<double> v(4 * width);
    for (int e = 0; e < rows.elements; ++e) {
      const auto w = wall_points(rows, e);
      for (int i = 0; i < 4; ++i) f(w[i], v.data() + std::size_t(i) * std::size_t(width));
      for (int c = 0; c < width; ++c) {
        const double* x = &v[c];
        out[(e * kinds) + c * stride] = 0.25 * (x[0] + x[width] + x[2 * width] + x[3 * width]);
        if (kinds == 3) {
          out[(e * kinds + 1) + c * stride] = 0.5 * (x[0] - x[width]);
          out[(e * kinds + 2) + c * stride] = 0.5 * (x[2 * width] - x[3 * width]);
        }
      }
    }
  }

  // Columns of `source` at every target of a point set: targets x cols. In single precision
  // only where asked (samples, face grids): a wall point sits a radius, maybe 1e-3 mm, from
  // its axis, finer than a float resolves at the block's coordinates. Where the set has chunk
  // boxes and far_ratio > 0, the chunks far from an element take its expansion (FarChunks).
  MatrixXd columns_at(const ChannelAxis& source, const PointSet& ps, bool single, const Vec3& origin,
                      double far_ratio) const;
  // The same in single precision over a slot layout, column-major (the samples' cached columns).
  std::vector<float> float_columns_at(const ChannelAxis& source, const PointSet& ps, const Vec3& origin,
                                      double far_ratio) const;
  void float_columns_into(const ChannelAxis& source, const PointSet& ps, const Vec3& origin, double far_ratio,
                          std::vector<float>& acc) const;
  // Columns of `source` at the rows of a channel (its own or another): its wall points' mean and
  // half-differences; wall image slots options.pair_far element lengths or more from an element
  // of the source see it as its multipole expansion (line_sink_fields.h, FarChunks).
  MatrixXd channel_at_rows(const LineSinkCache::ChannelBlock& rows, const ChannelAxis& source) const;
  // The same with the source's reflection in the part's void (when there is one).
  MatrixXd channel_at_rows(const LineSinkCache::ChannelBlock& rows, const LineSinkCache::ChannelBlock& source) const;
  // That reflection alone: source's layer at rows' rows (rows x source's cols).
  MatrixXd void_at_rows(const LineSinkCache::ChannelBlock& rows, const LineSinkCache::ChannelBlock& source) const;
  // Per convective face, the mean of `source`'s columns over its grid: faces x cols.
  MatrixXd face_means_of(const ChannelAxis& source) const;
  // Everything of one channel that does not depend on the others (line_sink_channel.cpp).
  std::shared_ptr<LineSinkCache::ChannelBlock> build_channel(const Channel& ch) const;
};

}  // namespace mtcs::thermal
