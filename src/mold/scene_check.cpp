#include "scene_check.h"

#include <cmath>
#include <iomanip>
#include <sstream>

namespace mtcs::mold {

using geometry::Vec3;

namespace {

constexpr const char* kAxes = "xyz";

std::string size_text(const Vec3& s) {
  std::ostringstream out;
  out.precision(4);
  out << s.x() << " x " << s.y() << " x " << s.z() << " mm";
  return out.str();
}

std::string length_text(double v) {
  std::ostringstream out;
  out.precision(6);
  out << v << " mm";
  return out.str();
}

// The first place where `inner` leaves `outer` by more than `tol`: "reaches x = 250 mm, beyond
// the block's +x face at 200 mm"; "" when inside.
std::string leaves(const Box& inner, const Box& outer, double tol) {
  for (int k = 0; k < 3; ++k) {
    if (inner.min[k] < outer.min[k] - tol)
      return std::string("reaches ") + kAxes[k] + " = " + length_text(inner.min[k]) + ", beyond the block's -" + kAxes[k] +
             " face at " + length_text(outer.min[k]);
    if (inner.max[k] > outer.max[k] + tol)
      return std::string("reaches ") + kAxes[k] + " = " + length_text(inner.max[k]) + ", beyond the block's +" + kAxes[k] +
             " face at " + length_text(outer.max[k]);
  }
  return "";
}

// The bounding box of a solid cylinder: each end widened by r sqrt(1 - u_k^2) along axis k.
Box cylinder_bounds(const geometry::Cylinder& c) {
  const Vec3 u = (c.p1 - c.p0).normalized();
  Vec3 reach;
  for (int k = 0; k < 3; ++k) reach[k] = c.radius * std::sqrt(std::max(0.0, 1 - u[k] * u[k]));
  return {c.p0.cwiseMin(c.p1) - reach, c.p0.cwiseMax(c.p1) + reach};
}

// The field a designer edits to move or resize a mesh: its translate or scale when written,
// else the mesh itself.
const YAML::Node pick(const YAML::Node& n, const char* preferred, std::string& field, const std::string& prefix) {
  if (n[preferred]) {
    field = prefix + "." + preferred;
    return n[preferred];
  }
  const char* fallback = n["mesh"] ? "mesh" : n["box"] ? "box" : "cylinder";
  field = prefix + "." + fallback;
  return n[fallback];
}

const std::string kScaleHint =
    "is the mesh in other units than mm? give a scale (0.001 from micrometres, 1000 from metres, 25.4 from inches)";

// A mesh part whose walls average under kMinMeanWall (twice its volume over its area, exact for
// a shell) was drawn in other units: inches keep a 120 mm part inside a normal block, so only its
// walls give it away. Each unit that makes the part fit the block with molded walls is named.
std::string unit_guess(const Vec3& part, double mean_wall, const Vec3& block) {
  struct Unit {
    const char* name;
    double scale;
  };
  std::ostringstream out;
  out.precision(3);
  for (const Unit u : {Unit{"inches", 25.4}, Unit{"centimetres", 10}, Unit{"metres", 1000}}) {
    const Vec3 s = part * u.scale;
    const double wall = mean_wall * u.scale;
    if ((s.array() <= block.array()).all() && s.maxCoeff() >= kMinGuessShare * block.maxCoeff() && wall >= kMinMeanWall &&
        wall <= kMaxMeanWall)
      out << (out.tellp() > 0 ? "; or in " : "in ") << u.name << "? scale: " << std::setprecision(6) << u.scale
          << " makes it " << size_text(s) << " with walls of " << std::setprecision(3) << wall << " mm";
  }
  return out.str();
}

}  // namespace

void check_scene(const io::YamlReader& r, const YAML::Node& root, const MoldSpec& spec) {
  const Box block = spec.block.box ? *spec.block.box : spec.block.mesh->mesh.bounds();
  const Vec3 size = block.size();
  const YAML::Node& b = root["block"];
  std::string field;
  for (int k = 0; k < 3; ++k)
    if (!(size[k] <= kMaxBlockExtent)) {
      const YAML::Node at = pick(b, spec.block.mesh ? "scale" : "box", field, "block");
      r.fail(at, field, "the block measures " + size_text(size) + ": more than " + length_text(kMaxBlockExtent) + " along " +
                            kAxes[k] + " is no mold block in mm" + (spec.block.mesh ? "; " + kScaleHint : ""));
    }
  const double tol = 1e-6 * size.maxCoeff();

  if (spec.cavity && !spec.cavity->is_patch()) {
    const YAML::Node& c = root["cavity"];
    const Box part = spec.cavity->bounds();
    const Vec3 ps = part.size();
    const std::string hint = spec.cavity->mesh ? "; " + kScaleHint : "";
    for (int k = 0; k < 3; ++k)
      if (ps[k] > size[k] + tol) {
        const YAML::Node at = pick(c, spec.cavity->mesh ? "scale" : "box", field, "cavity");
        r.fail(at, field, "the part measures " + size_text(ps) + ", larger than the block (" + size_text(size) +
                              ") along " + kAxes[k] + hint);
      }
    if (ps.maxCoeff() < kMinPartShare * size.maxCoeff()) {
      const YAML::Node at = pick(c, spec.cavity->mesh ? "scale" : "box", field, "cavity");
      std::string guess;
      if (spec.cavity->mesh) {
        const mesh::TriangleMesh& m = spec.cavity->mesh->mesh;
        guess = unit_guess(ps, 2 * m.signed_volume() / m.area(), size);
      }
      r.fail(at, field, "the part measures " + size_text(ps) + ", less than 1/" + std::to_string(std::lround(1 / kMinPartShare)) +
                            " of the block (" + size_text(size) + ")" + (guess.empty() ? hint : "; is the mesh " + guess));
    }
    if (spec.cavity->mesh && !c["scale"]) {
      const mesh::TriangleMesh& m = spec.cavity->mesh->mesh;
      const double mean_wall = 2 * m.signed_volume() / m.area();
      // Refused only where a unit would make a molded part that fills the block: a tiny test
      // solid in a large block is left alone.
      if (const std::string guess = unit_guess(ps, mean_wall, size); mean_wall < kMinMeanWall && !guess.empty()) {
        std::ostringstream wall;
        wall.precision(3);
        wall << mean_wall;
        r.fail(c["mesh"], "cavity.mesh",
               "the part's walls average " + wall.str() + " mm (twice its volume over its area), thinner than any molded part: " +
                   "is the mesh " + guess + " (a part truly this thin: write scale: 1)");
      }
    }
    if (const std::string out = leaves(part, block, tol); !out.empty()) {
      const YAML::Node at = pick(c, spec.cavity->mesh ? "translate" : "box", field, "cavity");
      // A small part outside the block is most often a mesh in other units, placed by its file.
      const bool small = ps.maxCoeff() < 0.1 * size.maxCoeff();
      r.fail(at, field, "the part (" + size_text(ps) + ") leaves the block: it " + out +
                            (spec.cavity->mesh ? "; place it with cavity.translate (and rotate)" : "") +
                            (spec.cavity->mesh && small ? "; it is also small for the block (" + size_text(size) + "): " + kScaleHint : ""));
    }
  }

  for (std::size_t i = 0; i < spec.keep_outs.size(); ++i) {
    const KeepOut& k = spec.keep_outs[i];
    const YAML::Node& n = root["keep_outs"][i];
    const std::string prefix = io::indexed("keep_outs", i);
    Box bounds;
    if (k.cylinder) {
      const geometry::Cylinder& cyl = *k.cylinder;
      if (!((cyl.p1 - cyl.p0).norm() > tol))
        r.fail(n["cylinder"]["p1"], prefix + ".cylinder.p1",
               "keep-out '" + k.name + "' is a pin of zero length: p0 and p1 are the same point; give its two ends");
      bounds = cylinder_bounds(cyl);
    } else {
      bounds = k.mesh->mesh.bounds();
    }
    if (const std::string out = leaves(bounds, block, tol); !out.empty()) {
      const YAML::Node at = pick(n, k.mesh ? "translate" : "cylinder", field, prefix);
      r.fail(at, field, "keep-out '" + k.name + "' leaves the block: it " + out +
                            "; keep-outs lie in the block's steel (trim a pin at the block's face)");
    }
  }
}

}  // namespace mtcs::mold
