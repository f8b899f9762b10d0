#pragma once
// The finite-volume grid over the block: what each cell is (steel, cavity, or a channel's) and
// where the links from steel cell centres enter a bore. Private to src/thermal.

#include <array>
#include <cstddef>
#include <limits>
#include <unordered_map>
#include <vector>

#include "mtcs/thermal/finite_volume.h"

namespace mtcs::thermal::fv {

constexpr int kSteel = FvField::kSteel, kVoid = FvField::kCavity;  // a channel's cells hold its index
// The temperature of a cell or point outside the steel.
inline constexpr double kNoTemperature = std::numeric_limits<double>::quiet_NaN();

// Face f of the block (BlockFace order) is normal to axis f / 2, at the max end when f is odd;
// the direction dir of a link (-x, +x, -y, ...) uses the same numbering.
inline int face_axis(int face) { return face / 2; }
inline bool face_is_max(int face) { return face % 2 == 1; }
// The two axes spanning face f's plane, as (b, c).
inline std::array<int, 2> face_plane_axes(int face) { return {(face / 2 + 1) % 3, (face / 2 + 2) % 3}; }

// floor(u) as an int, clamped to [-2, n + 1]: a far point stays representable.
int clamped_floor(double u, int n);

// A grid link from a steel cell's centre that enters a bore before reaching its other end.
struct Cut {
  double t;       // distance along the link, mm
  double cosine;  // |n . e| at the wall
  int channel;
};

struct CellRange {
  std::array<int, 3> lo, hi;  // inclusive
};

class Grid {
 public:
  // Sets field's cells, origin and spacing. Throws std::invalid_argument on an unusable model.
  Grid(const Model& model, const FvOptions& options, FvField& field);

  int kind(int i, int j, int k) const { return kind_[field_.index(i, j, k)]; }
  bool inside(int i, int j, int k) const {
    return i >= 0 && j >= 0 && k >= 0 && i < field_.cells[0] && j < field_.cells[1] && k < field_.cells[2];
  }
  // The cut of the link from steel cell `cell` in direction dir, or null.
  const Cut* cut(std::size_t cell, int dir) const {
    const auto it = cuts_.find(cell * 6 + std::size_t(dir));
    return it == cuts_.end() ? nullptr : &it->second;
  }

  // The cells whose centres may lie in [lo, hi], grown by `margin` cells, clamped to the grid.
  CellRange range(const Vec3& lo, const Vec3& hi, int margin) const;
  template <class F>
  void for_cells(const CellRange& r, F&& f) const {
    for (int k = r.lo[2]; k <= r.hi[2]; ++k)
      for (int j = r.lo[1]; j <= r.hi[1]; ++j)
        for (int i = r.lo[0]; i <= r.hi[0]; ++i) f(i, j, k);
  }

 private:
  void mark_void();
  void mark_channels();
  void cut_links();
  geometry::Cylinder cylinder(int c) const;
  CellRange channel_range(int c, int margin) const;

  const Model& model_;
  FvField& field_;
  std::vector<int> kind_;
  std::unordered_map<std::size_t, Cut> cuts_;
};

}  // namespace mtcs::thermal::fv
