#pragma once
// The scene checked as a whole once every section is read (issue 16, item 2): what each field
// allows alone can still make no mold together. A part or keep-out outside the block, a part
// in other units than the block (a micrometre mesh 1000 times the block), a block larger than any
// mold, a pin of zero length: each is refused with the measured sizes and a hint.

#include <yaml-cpp/yaml.h>

#include "mtcs/io/yaml_reader.h"
#include "mtcs/mold/mold_spec.h"

namespace mtcs::mold {

// The most triangles a mesh of the spec may have: beyond it the reader says to simplify the
// mesh instead of building BVHs and samples until memory runs out.
inline constexpr double kMaxSpecTriangles = 5e6;
// The largest block extent accepted, mm (10 m): beyond it the numbers are not a mold in mm.
inline constexpr double kMaxBlockExtent = 1e4;
// A part whose largest extent is below this share of the block's largest extent is taken for a
// mesh in other units (metres, inches) and refused with a hint about `scale`.
inline constexpr double kMinPartShare = 0.01;
// A mesh part whose walls average (2 volume / area) under this many mm, with no `scale` written,
// is taken for a mesh in inches, centimetres or metres when one of them makes a molded part
// (walls up to the max) that fits the block.
inline constexpr double kMinMeanWall = 0.25;
inline constexpr double kMaxMeanWall = 30;
// A guessed unit must make the part's largest extent at least this share of the block's (a
// block is sized to its part: the bundled molds 0.4-0.7).
inline constexpr double kMinGuessShare = 0.3;

// Throws io::InputError at the field to change (`root` is the spec's document).
void check_scene(const io::YamlReader& r, const YAML::Node& root, const MoldSpec& spec);

}  // namespace mtcs::mold
