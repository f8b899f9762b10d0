// Bad numbers where the CSV and front readers take input (issue 15, item 5): NaN, infinities,
// numbers beyond double are refused at their line, column and field; denormals, negative zero
// and 1e308 are read exactly.

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "mtcs/io/cylinders_csv.h"
#include "mtcs/io/front_file.h"
#include "mtcs/io/input_error.h"
#include "mtcs/io/pairs_csv.h"
#include "mtcs/io/points_csv.h"
#include "support/scratch_file.h"

using mtcs::io::InputError;
namespace fs = std::filesystem;

namespace {

std::string write(const std::string& name, const std::string& text) {
  const fs::path dir = mtcs_test::scratch_dir("io_bad_numbers");
  std::ofstream(dir / name) << text;
  return (dir / name).string();
}

template <class Read>
InputError error_of(Read read, const std::string& path) {
  try {
    read(path);
  } catch (const InputError& e) {
    return e;
  }
  FAIL("no error for " << path);
  throw;
}

}  // namespace

TEST_CASE("bad numbers: a CSV cell of NaN, inf or beyond double is refused at its cell", "[io][bad-numbers]") {
  for (const std::string v : {"nan", "NaN", "-nan", "inf", "-inf", "infinity", "1e309", "-2e308"}) {
    INFO(v);
    const auto path = write("points.csv", "x,y,z\n1,2,3\n4," + v + ",6\n");
    const auto e = error_of([](const std::string& p) { return mtcs::io::read_points_csv(p); }, path);
    CHECK(e.file() == path);
    CHECK(e.line() == 3);
    CHECK(e.column() == 3);
    CHECK(e.field() == "y");
  }
  const auto e = error_of([](const std::string& p) { return mtcs::io::read_points_csv(p); }, write("big.csv", "x,y,z\n1e400,0,0\n"));
  CHECK_THAT(std::string(e.what()), Catch::Contains("beyond the range of a double"));
}

TEST_CASE("bad numbers: denormals, -0 and 1e308 in a CSV are read exactly", "[io][bad-numbers]") {
  const auto points = mtcs::io::read_points_csv(write("exact.csv", "x,y,z\n4.9e-324,-0,1e308\n-1e-310,0,-1.7976931348623157e308\n"));
  REQUIRE(points.size() == 2);
  CHECK(points[0].x() == 4.9e-324);
  CHECK(points[0].y() == 0.0);
  CHECK(std::signbit(points[0].y()));
  CHECK(points[0].z() == 1e308);
  CHECK(points[1].x() == -1e-310);
  CHECK(points[1].z() == -1.7976931348623157e308);
  const auto cylinders = mtcs::io::read_cylinders_csv(write("c.csv", "id,p0x,p0y,p0z,p1x,p1y,p1z,r\na,0,0,0,1,0,0,-0\nb,0,0,0,1,0,0,5e-324\n"));
  CHECK(cylinders[0].cylinder.radius == 0.0);  // -0 is not a negative radius
  CHECK(cylinders[1].cylinder.radius == 5e-324);
  CHECK(error_of(mtcs::io::read_cylinders_csv, write("n.csv", "id,p0x,p0y,p0z,p1x,p1y,p1z,r\na,0,0,0,1,0,0,-1e-320\n")).field() == "r");
}

TEST_CASE("bad numbers: a front file refuses NaN and infinities at their column", "[io][bad-numbers]") {
  for (const std::string v : {"nan", "inf", "-inf", "1e400"}) {
    INFO(v);
    const auto e = error_of(mtcs::io::read_front, write("front.txt", "# ref 2 2\n1 1\n0.5   " + v + "\n"));
    CHECK(e.line() == 3);
    CHECK(e.column() == 7);
    CHECK(e.field() == "point");
  }
  const auto f = mtcs::io::read_front(write("ok.txt", "1e-310 -0\n1e308 0\n"));
  CHECK(f.points[0][0] == 1e-310);
  CHECK(f.points[1][0] == 1e308);
}

TEST_CASE("bad numbers: the pairs CSV refuses NaN, infinities and 1e400 at their cell, reads denormals and -0",
          "[io][bad-numbers]") {
  const std::string head = "id,p0x,p0y,p0z,p1x,p1y,p1z,r0,q0x,q0y,q0z,q1x,q1y,q1z,r1\n";
  for (const std::string v : {"nan", "NaN", "inf", "-inf", "1e400", "-1e999"}) {
    INFO(v);
    const auto e = error_of(mtcs::io::read_pairs_csv, write("pairs.csv", head + "a,0,0,0,10,0,0,1,0,5,0,10," + v + ",0,2\n"));
    CHECK(e.line() == 2);
    CHECK(e.column() == 27);
    CHECK(e.field() == "q1y");
  }
  const auto pairs = mtcs::io::read_pairs_csv(write("ok.csv", head + "a,-0,4.9e-324,0,10,0,0,1,0,5,0,1e308,5,0,2\n"));
  REQUIRE(pairs.size() == 1);
  CHECK(pairs[0].a.p0.y() == 4.9e-324);
  CHECK(pairs[0].a.p0.x() == 0.0);
  CHECK(pairs[0].b.p1.x() == 1e308);
}
