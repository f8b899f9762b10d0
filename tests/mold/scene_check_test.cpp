// The scene checked as a whole when the spec loads (issue 16, item 2). Each test names a defect
// from the "Why" that used to pass: scale and placement mistakes, a block 1e300 mm tall,
// a zero-length pin, `use: [cost, cost]`, a self-intersecting part that only `mtcs interfere`
// refused. Meshes are placed with the spec's scale, rotate and translate alone.

#include <catch2/catch.hpp>
#include <filesystem>
#include <sstream>

#include "../support/scratch_file.h"
#include "mtcs/io/input_error.h"
#include "mtcs/mold/mold_spec.h"
#include "support/thrown_by.h"

using namespace mtcs;
using geometry::Vec3;
namespace fs = std::filesystem;

namespace {

fs::path write(const std::string& name, const std::string& text) {
  return mtcs_test::write_scratch("scene_check_test", name, text);
}

// OFF text of closed, outward-oriented boxes (12 triangles each); two overlapping boxes in one
// file make a closed surface that intersects itself.
std::string boxes_off(const std::vector<std::array<double, 6>>& boxes) {
  std::ostringstream v, f;
  int base = 0;
  for (const auto& b : boxes) {
    for (int i = 0; i < 8; ++i)
      v << b[(i & 1) ? 3 : 0] << ' ' << b[(i & 2) ? 4 : 1] << ' ' << b[(i & 4) ? 5 : 2] << '\n';
    // Corner i has x from bit 0, y from bit 1, z from bit 2; each face counter-clockwise from outside.
    const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads) {
      f << "3 " << base + q[0] << ' ' << base + q[1] << ' ' << base + q[2] << '\n';
      f << "3 " << base + q[0] << ' ' << base + q[2] << ' ' << base + q[3] << '\n';
    }
    base += 8;
  }
  return "OFF\n" + std::to_string(base) + " " + std::to_string(boxes.size() * 12) + " 0\n" + v.str() + f.str();
}

const std::string kBlock = "block: {box: {min: [0, 0, 0], max: [200, 210, 110]}}\n";

// A 100 x 60 x 20 mm part, written in micrometres: 1e5 x 6e4 x 2e4 units from the origin.
const std::string kPartUm = boxes_off({{0, 0, 0, 1e5, 6e4, 2e4}});

io::InputError error_of(const std::string& text, const std::string& name = "spec.yaml") {
  const auto p = write(name, text);
  return mtcs_test::thrown_by<io::InputError>([&] { mold::load_mold_spec(p.string()); }, text);
}

}  // namespace

TEST_CASE("scene check: a part mesh in micrometres (1000x the block) is refused with its size and a scale hint",
          "[mold][scene]") {
  write("part_um.off", kPartUm);
  const io::InputError e = error_of(kBlock + "cavity:\n  mesh: part_um.off\n");
  CHECK(e.line() == 3);
  CHECK(e.field() == "cavity.mesh");
  CHECK_THAT(std::string(e.what()), Catch::Contains("the part measures 1e+05 x 6e+04 x 2e+04 mm, larger than the block"));
  CHECK_THAT(std::string(e.what()), Catch::Contains("0.001 from micrometres"));
}

TEST_CASE("scene check: the same micrometre part with scale 0.001 and a translate loads where it was placed",
          "[mold][scene]") {
  write("part_um.off", kPartUm);
  const auto spec = mold::load_mold_spec(
      write("scaled.yaml", kBlock + "cavity:\n  mesh: part_um.off\n  scale: 0.001\n  translate: [50, 75, 60]\n").string());
  const auto b = spec.cavity->bounds();
  CHECK(b.min.isApprox(Vec3(50, 75, 60)));
  CHECK(b.max.isApprox(Vec3(150, 135, 80)));
}

TEST_CASE("scene check: rotate turns a mesh about an axis through the origin before translate", "[mold][scene]") {
  write("bar.off", boxes_off({{0, 0, 0, 100, 20, 10}}));
  // 90 degrees about +z (right-handed): x -> y, y -> -x; the bar now spans x in [-20, 0], y in [0, 100].
  const auto spec = mold::load_mold_spec(
      write("rotated.yaml", kBlock + "cavity:\n  mesh: bar.off\n  rotate: {axis: [0, 0, 1], degrees: 90}\n"
                                     "  translate: [120, 50, 40]\n").string());
  const auto b = spec.cavity->bounds();
  CHECK(b.min.isApprox(Vec3(100, 50, 40), 1e-9));
  CHECK(b.max.isApprox(Vec3(120, 150, 50), 1e-9));
  // Per-axis scale and a list of rotations, in order: x by 2 (200 long) ... then about +y by 90: x -> -z.
  const auto spec2 = mold::load_mold_spec(
      write("rotated2.yaml", kBlock + "cavity:\n  mesh: bar.off\n  scale: [0.5, 1, 1]\n"
                                      "  rotate: [{axis: [0, 0, 1], degrees: 90}, {axis: [1, 0, 0], degrees: 90}]\n"
                                      "  translate: [100, 50, 50]\n").string());
  // After scale: [0,50]x[0,20]x[0,10]; about z: [-20,0]x[0,50]x[0,10]; about x (y -> z, z -> -y):
  // [-20,0]x[-10,0]x[0,50]; translated: [80,100]x[40,50]x[50,100].
  const auto c = spec2.cavity->bounds();
  CHECK(c.min.isApprox(Vec3(80, 40, 50), 1e-9));
  CHECK(c.max.isApprox(Vec3(100, 50, 100), 1e-9));
}

TEST_CASE("scene check: a part 10x larger than the block is refused", "[mold][scene]") {
  write("huge.off", boxes_off({{0, 0, 0, 1000, 600, 200}}));
  CHECK_THAT(std::string(error_of(kBlock + "cavity: {mesh: huge.off}\n").what()),
             Catch::Contains("the part measures 1000 x 600 x 200 mm, larger than the block (200 x 210 x 110 mm) along x"));
}

TEST_CASE("scene check: a part in metres (1/1000 of its size) is refused as too small with a scale hint", "[mold][scene]") {
  write("part_m.off", boxes_off({{0.05, 0.05, 0.05, 0.15, 0.11, 0.07}}));
  const io::InputError e = error_of(kBlock + "cavity: {mesh: part_m.off}\n");
  CHECK_THAT(std::string(e.what()), Catch::Contains("less than 1/100 of the block"));
  CHECK_THAT(std::string(e.what()), Catch::Contains("is the mesh in metres? scale: 1000 makes it 100 x 60 x 20 mm"));
}

namespace {

// A closed hollow box in inches: 4.7 x 3.1 x 1.6 in outside (120 x 80 x 40 mm), walls of 0.1 in
// (2.54 mm); the inner box's faces turned inwards, so the solid between them is outward-oriented.
std::string hollow_box_inches() {
  const double o[6] = {1, 1, 1, 1 + 120 / 25.4, 1 + 80 / 25.4, 1 + 40 / 25.4}, w = 0.1;
  std::string text = boxes_off({{o[0], o[1], o[2], o[3], o[4], o[5]}, {o[0] + w, o[1] + w, o[2] + w, o[3] - w, o[4] - w, o[5] - w}});
  // Swap the last two indices of the inner box's 12 triangles (the file's last 12 lines).
  std::istringstream in(text);
  std::ostringstream out;
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (i + 12 >= lines.size()) {
      int n, a, b, c;
      std::istringstream(lines[i]) >> n >> a >> b >> c;
      out << "3 " << a << ' ' << c << ' ' << b << '\n';
    } else {
      out << lines[i] << '\n';
    }
  }
  return out.str();
}

}  // namespace

TEST_CASE("scene check: a shell part in inches (issue 45: accepted silently) is refused by its walls, naming inches and the scale",
          "[mold][scene]") {
  write("lid_in.off", hollow_box_inches());
  const io::InputError e = error_of(kBlock + "cavity:\n  mesh: lid_in.off\n");
  CHECK(e.line() == 3);
  CHECK(e.field() == "cavity.mesh");
  const std::string what = e.what();
  CHECK_THAT(what, Catch::Contains("the part's walls average 0.0"));
  CHECK_THAT(what, Catch::Contains("is the mesh in inches? scale: 25.4 makes it 120 x 80 x 40 mm"));
  // Given its scale, the same file loads as the 120 x 80 x 40 mm part; `scale: 1` keeps it as drawn.
  const auto spec = mold::load_mold_spec(write("lid_scaled.yaml", kBlock + "cavity: {mesh: lid_in.off, scale: 25.4}\n").string());
  CHECK(spec.cavity->bounds().size().isApprox(Vec3(120, 80, 40), 1e-5));
  CHECK_NOTHROW(mold::load_mold_spec(write("lid_tiny.yaml", kBlock + "cavity: {mesh: lid_in.off, scale: 1}\n").string()));
}

TEST_CASE("scene check: a small part left where its file put it is refused with a scale hint", "[mold][scene]") {
  // The fandisk case of docs/first-mold.md: 4.8 x 5.2 x 2.7 units, z from -2.7 to 0.
  write("small.off", boxes_off({{0, 12.6, -2.68, 4.83, 17.85, 0}}));
  const io::InputError e = error_of(kBlock + "cavity:\n  mesh: small.off\n");
  CHECK(e.field() == "cavity.mesh");
  CHECK_THAT(std::string(e.what()), Catch::Contains("leaves the block: it reaches z = -2.68 mm"));
  CHECK_THAT(std::string(e.what()), Catch::Contains("it is also small for the block (200 x 210 x 110 mm)"));
  CHECK_THAT(std::string(e.what()), Catch::Contains("give a scale"));
}

TEST_CASE("scene check: a part partly outside the block is refused, naming the face it crosses", "[mold][scene]") {
  write("part.off", boxes_off({{0, 0, 0, 100, 60, 20}}));
  const io::InputError e = error_of(kBlock + "cavity: {mesh: part.off, translate: [150, 75, 40]}\n");
  CHECK(e.field() == "cavity.translate");
  CHECK_THAT(std::string(e.what()), Catch::Contains("leaves the block: it reaches x = 250 mm, beyond the block's +x face at 200 mm"));
  // A box cavity too.
  CHECK_THAT(std::string(error_of(kBlock + "cavity: {box: {min: [50, 50, 100], max: [150, 150, 120]}}\n").what()),
             Catch::Contains("reaches z = 120 mm, beyond the block's +z face at 110 mm"));
}

TEST_CASE("scene check: a keep-out outside the block is refused", "[mold][scene]") {
  const io::InputError e = error_of(kBlock + "keep_outs:\n  - {name: pin, cylinder: {p0: [250, 50, 0], p1: [250, 50, 60], radius: 3}}\n");
  CHECK(e.field() == "keep_outs[0].cylinder");
  CHECK_THAT(std::string(e.what()), Catch::Contains("keep-out 'pin' leaves the block: it reaches x = 253 mm"));
  write("lifter.off", boxes_off({{0, 0, 0, 20, 20, 80}}));
  CHECK_THAT(std::string(error_of(kBlock + "keep_outs:\n  - {name: lifter, mesh: lifter.off, translate: [10, 10, 50]}\n").what()),
             Catch::Contains("keep-out 'lifter' leaves the block: it reaches z = 130 mm"));
}

TEST_CASE("scene check: a zero-length pin is refused", "[mold][scene]") {
  const io::InputError e = error_of(kBlock + "keep_outs:\n  - {name: pin, cylinder: {p0: [50, 50, 0], p1: [50, 50, 0], radius: 3}}\n");
  CHECK(e.field() == "keep_outs[0].cylinder.p1");
  CHECK_THAT(std::string(e.what()), Catch::Contains("pin of zero length"));
}

TEST_CASE("scene check: a block 1e300 mm tall is refused, and one 1e6 mm tall too", "[mold][scene]") {
  const io::InputError e = error_of("block: {box: {min: [0, 0, 0], max: [200, 210, 1e300]}}\n");
  CHECK(e.field() == "block.box.max[2]");
  const io::InputError f = error_of("block: {box: {min: [0, 0, 0], max: [200, 210, 1e6]}}\n");
  CHECK(f.field() == "block.box");
  CHECK_THAT(std::string(f.what()), Catch::Contains("more than 10000 mm along z is no mold block in mm"));
}

TEST_CASE("scene check: use: [cost, cost] is refused", "[mold][scene]") {
  const io::InputError e = error_of(kBlock + "objectives: {use: [cost, cost]}\n");
  CHECK(e.field() == "objectives.use[1]");
  CHECK_THAT(std::string(e.what()), Catch::Contains("listed twice"));
}

TEST_CASE("scene check: a self-intersecting part is refused at load, as mtcs interfere refuses it", "[mold][scene]") {
  // Two boxes overlapping: closed and oriented, but the surfaces cross.
  write("crossed.off", boxes_off({{50, 50, 40, 110, 90, 60}, {90, 70, 50, 150, 120, 70}}));
  const io::InputError e = error_of(kBlock + "cavity: {mesh: crossed.off}\n");
  CHECK(e.field() == "cavity.mesh");
  CHECK_THAT(std::string(e.what()), Catch::Contains("not the surface of a solid"));
  // The same for a mesh keep-out.
  CHECK_THAT(std::string(error_of(kBlock + "keep_outs: [{name: lifter, mesh: crossed.off}]\n").what()),
             Catch::Contains("not the surface of a solid"));
}

TEST_CASE("scene check: scale and rotate are refused beside a box or cylinder, and a zero rotation axis", "[mold][scene]") {
  CHECK(error_of(kBlock + "cavity: {box: {min: [50, 50, 50], max: [60, 60, 60]}, scale: 2}\n").field() == "cavity.scale");
  write("part.off", boxes_off({{0, 0, 0, 100, 60, 20}}));
  CHECK(error_of(kBlock + "cavity: {mesh: part.off, rotate: {axis: [0, 0, 0], degrees: 30}}\n").field() ==
        "cavity.rotate.axis");
  CHECK(error_of(kBlock + "cavity: {mesh: part.off, scale: -1}\n").field() == "cavity.scale");
}

TEST_CASE("scene check: a NaN vertex, a bad face index and a vertex at 1e300 in the part are refused at their line",
          "[mold][scene]") {
  // Used to be a generic "cannot read mesh" without a line (NaN, bad index) and, for 1e300,
  // "oriented inwards". Line 10 of the box's OFF is vertex 7, line 11 its first face.
  auto with_line = [](std::string text, int line, const std::string& replacement) {
    std::size_t at = 0;
    for (int l = 1; l < line; ++l) at = text.find('\n', at) + 1;
    return text.replace(at, text.find('\n', at) - at, replacement);
  };
  const std::string box = boxes_off({{50, 50, 40, 110, 90, 60}});
  write("nan.off", with_line(box, 10, "110 90 nan"));
  write("far.off", with_line(box, 10, "110 90 1e300"));
  write("index.off", with_line(box, 11, "3 0 2 9"));
  for (const auto& [file, where] : {std::pair{"nan.off", "nan.off:10:8: vertex 7: coordinate z is 'nan'"},
                                    std::pair{"far.off", "far.off:10:8: vertex 7: coordinate z is '1e300'"},
                                    std::pair{"index.off", "index.off:11: face 0 refers to vertex 9"}}) {
    INFO(file);
    const io::InputError e = error_of(kBlock + "cavity: {mesh: " + file + "}\n");
    CHECK(e.field() == "cavity.mesh");
    CHECK_THAT(std::string(e.what()), Catch::Contains(where));
    CHECK_THAT(std::string(e.what()), !Catch::Contains("oriented") && !Catch::Contains("cannot read mesh"));
  }
}
