#pragma once
// The line-sink tiers (issue 11): the bores as line sinks in the block, superposed with the heat
// input's potential and the block faces' images. Built once per Setting + Samples (everything
// that does not depend on the layout is computed there); evaluated per layout with a cache of
// per-channel influence columns, so a layout that differs from the last one in a few channels
// recomputes only those channels.
//
//   T1   one strength per length shared by every bore (heat in minus face losses, by length);
//        the free constant is fixed by the bores' length-weighted mean wall temperature.
//   T2   one strength per element (elements per channel), collocated: the wall's circumferential
//        mean equals coolant + q'/(pi D h).
//   T2d  T2 plus two transverse line dipoles per element: the wall's first circumferential
//        harmonic obeys the film condition (the bore's reaction to a transverse gradient).
//
// The block's faces: adiabatic (film 0) and convective faces reflect the sources with the same
// sign; a convective face also carries an unknown uniform loss, h A (face mean - ambient),
// collocated at a grid on the face; an isothermal face (film infinite) reflects with the
// opposite sign and fixes the free constant at its ambient. `images` reflection levels are
// summed exactly, the farther ones up to `far_images` as the charge and dipole of the block's
// image. That split assumes a compact block (no side much shorter than the others): for a slab,
// sum more levels exactly and set far_images to 0.
//
// Default (T2d, 4 elements) on the reference block: RMS 0.14 K against FreeFem++ P2, 0.31 ms
// per full evaluation, 0.135 ms with one bore changed (experiments/thermal/line_sinks.md).

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "mtcs/thermal/model.h"

namespace mtcs::thermal {

enum class Tier { T1, T2, T2d };

struct LineSinkOptions {
  Tier tier = Tier::T2d;
  int elements = 4;     // per channel
  int images = 2;       // reflection levels summed exactly: 1 = the six faces, 2 = also the
                        // double reflections (edges, and the translations by twice the block)
  int far_images = 6;   // up to this level, the farther images as the block's charge + dipole
  int sample_images = 0;   // levels summed exactly at the samples (at most `images`; -1: all);
                           // fewer is cheaper, the rest joins the far lattice there. 0: one,
                           // or all where the far lattice misses the heated wall's own images
                           // at the samples by over 5 % (a cavity reaching two faces)
  int face_grid = 4;    // face_grid^2 points per convective face for its mean temperature
  bool single_precision = true;  // the per-channel columns at the samples in float
  double far_expansion = 0.35;   // at samples and face points whose chunk lies h / this or
                                 // farther from each element's centre (h: half its length), the
                                 // element's multipole expansion to P6 (relative error bounds
                                 // 3e-5 sink, 1.3e-3 dipole at 0.35); 0: the closed forms everywhere
  double heat_grid = 4;          // mm: the heat input's field tabulated for the collocation
                                 // points 2 cells or more from it (0: always summed exactly);
                                 // a large block: a coarser grid, this one around the heat
  double pair_far = 2;  // element lengths: an image slot of a channel's wall points (its own
                        // or another's rows) this far from an element's centre sees the element
                        // as its multipole expansion to P6 (q <= 1 / (2 pair_far); 0: every
                        // block exact; with single_precision only, the double path stays exact)
  double void_panel = 0;  // mm: > 0 with a cavity (mesh or box): the part's void as a surface of
                          // panels this wide (src/thermal/cavity/void_surface.h); 0: the void is steel
  bool keep_potentials = true;  // the void's potentials at the samples kept in memory for the next
                                // model at the same samples (a cycle's next film); false for
                                // points seen once (a field's vertices, chunk by chunk)
};

// The per-channel and per-pair influence blocks of recent evaluations, keyed by the exact
// geometry (axis ends, radius); coolant and film are applied at assembly, so changing them costs
// nothing. Belongs to one LineSinkModel. It keeps the blocks of several layouts (an ES child's
// parent is rarely the layout evaluated just before it on this thread) up to a memory budget;
// past it, the blocks unused for longest are dropped. What is cached never changes a result:
// a block is a function of its key alone.
class LineSinkCache {
 public:
  explicit LineSinkCache(std::size_t budget_bytes = std::size_t(64) << 20);
  ~LineSinkCache();
  LineSinkCache(LineSinkCache&&) noexcept;
  LineSinkCache& operator=(LineSinkCache&&) noexcept;
  std::size_t channels_computed = 0;  // columns computed (misses), over the cache's life
  std::size_t channels_reused = 0;    // hits
  void clear();
  struct ChannelBlock;  // defined inside the module (src/thermal/line_sinks/line_sink_model.h)
  struct PairBlock;

 private:
  friend class LineSinkModel;
  struct Tables;  // the blocks by key (src/thermal/line_sinks/line_sinks.cpp)
  std::unique_ptr<Tables> tables_;
  std::size_t budget_;
  std::size_t bytes_ = 0;  // held by the channels' and pairs' blocks
  std::uint64_t evaluation_ = 0;
  const void* owner_ = nullptr;
};

struct LineSinkSolution {
  std::vector<double> temperature;    // at the samples, degrees C
  std::vector<double> channel_heat;   // W into each channel's coolant
  double face_heat = 0;               // W lost through the convective faces
  double heat_in = 0;                 // W entering through the heated triangles
};

class LineSinkModel {
 public:
  LineSinkModel(const Setting& setting, const Samples& samples, LineSinkOptions options = {});
  // The same model (setting and options) at other samples. What does not depend on them is
  // shared, as between any models of one setting in a process (the part's void: most of a mesh
  // mold's build); the temperatures are a fresh build's, bit for bit. keep_potentials: as
  // LineSinkOptions::keep_potentials.
  LineSinkModel(const LineSinkModel& like, const Samples& samples, bool keep_potentials = true);
  ~LineSinkModel();
  LineSinkModel(LineSinkModel&&) noexcept;

  LineSinkSolution solve(std::span<const Channel> channels, LineSinkCache& cache) const;
  std::vector<double> temperatures(std::span<const Channel> channels, LineSinkCache& cache) const {
    return solve(channels, cache).temperature;
  }

  const LineSinkOptions& options() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace mtcs::thermal
