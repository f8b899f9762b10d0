#pragma once
// The cavity samples in tiles of 32 neighbours, for the nearest-bore distances of the thermal
// proxies: m_i = min_b |s_i - segment_b|^2 over a circuit's bores, in single precision relative
// to the block's corner.
//
// A tile takes the bores nearest box first and skips a bore whose box is farther than every
// distance of the tile so far: most tiles score two or three bores of a circuit, not all. A skip
// is safe by a margin far above the rounding of the distances, so m is a plain loop's over every
// bore, bit for bit (tests/eval/tiled_samples_test.cpp).

#include <cstdint>
#include <vector>

#include "mtcs/geometry/primitives.h"
#include "surface_samples.h"

namespace mtcs::eval {

struct FlowSegment {
  geometry::Vec3 start, end;
};

class TiledSamples {
 public:
  static constexpr std::size_t kTile = 32;

  // `origin`: the block's corner (single-precision coordinates are relative to it).
  TiledSamples(const SurfaceSamples& samples, const geometry::Vec3& origin);

  // Values per sample live in slots, tile after tile; the last tile is padded with copies of
  // its first sample (so a padded slot holds that sample's value).
  std::size_t slots() const { return xs_.size(); }
  // The slot of sample i (in the samples' order).
  std::uint32_t slot(std::size_t i) const { return slot_[i]; }

  // m[k] = min over the segments of the squared distance from slot k's sample, for every slot.
  void nearest_squared(const FlowSegment* first, const FlowSegment* last, float* m) const;

  struct Tile {
    std::uint32_t begin;    // its slots [begin, begin + kTile)
    geometry::Vec3 lo, hi;  // its samples' box, in single-precision coordinates
    double margin;          // the rounding of its samples' coordinates, bounded
  };

 private:
  geometry::Vec3 origin_;
  std::vector<float> xs_, ys_, zs_;  // relative to origin_, per slot
  std::vector<std::uint32_t> slot_;  // sample -> slot
  std::vector<Tile> tiles_;
};

}  // namespace mtcs::eval
