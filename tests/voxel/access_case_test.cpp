// Case files: errors name file:line:column and the field; writing a computed map reproduces the
// case file byte for byte when the map equals the expected one.

#include <catch2/catch.hpp>
#include <fstream>
#include <sstream>

#include "mtcs/io/input_error.h"
#include "mtcs/voxel/accessibility_map.h"
#include "support/scratch_file.h"
#include "support/thrown_by.h"
#include "voxel/case_files.h"
#include "support/paths.h"

using namespace mtcs;
using namespace mtcs::voxel;

namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The error message of reading `text` as a case file.
std::string error_of(const std::string& text) {
  const std::string path = mtcs_test::write_scratch("access_case", "case.txt", text).string();
  return mtcs_test::thrown_by<io::InputError>([&] { read_access_case(path); }, text).what();
}

}  // namespace

TEST_CASE("writing the computed map reproduces the case file", "[voxel][case]") {
  const std::string path = std::string(MTCS_TEST_DATA) + "/access_maps/drilling_homer_p05.txt";
  const AccessCase c = read_access_case(path);
  const AccessMap map = compute_access_map(testing::case_octree(c), c.pivot, c.tool, c.sphere);
  std::ostringstream out;
  write_access_case(out, c, map.rows());
  CHECK(out.str() == slurp(path));
  // A different map changes exactly the collisions line and the cells.
  auto rows = map.rows();
  rows[0][0] = rows[0][0] == '1' ? '0' : '1';
  std::ostringstream changed;
  write_access_case(changed, c, rows);
  CHECK(changed.str() != slurp(path));
}

TEST_CASE("case-file errors name the line, column and field", "[voxel][case]") {
  const std::string good = slurp(std::string(MTCS_TEST_DATA) + "/access_maps/drilling_homer_p05.txt");
  const auto replace = [&](const std::string& from, const std::string& to) {
    std::string s = good;
    const auto at = s.find(from);
    REQUIRE(at != std::string::npos);
    return s.replace(at, from.size(), to);
  };
  CHECK_THAT(error_of(replace("voxel_size 0.390625", "voxel_size abc")), Catch::Contains(":10:12: field 'voxel_size'"));
  CHECK_THAT(error_of(replace("grid 128 128 128", "grid 128 128")), Catch::Contains("field 'grid'"));
  CHECK_THAT(error_of(replace("cyl a 0.0000", "cyl a -1.0")), Catch::Contains("field 'cyl.a': must be >= 0"));
  CHECK_THAT(error_of(replace("am_cols 32", "am_cols 31")), Catch::Contains("field 'am': row of 32 cells, expected 31"));
  CHECK_THAT(error_of(replace("pivot ", "pivots ")), Catch::Contains("unknown key 'pivots'"));
  CHECK_THAT(error_of(good.substr(0, good.find("am\n") + 3 + 2 * 33)), Catch::Contains("field 'am': file ends"));
  CHECK_THAT(error_of(replace("pivot ", "# pivot ")), Catch::Contains("field 'pivot': missing"));
  CHECK_NOTHROW(read_access_case(mtcs_test::write_scratch("access_case", "good.txt", good).string()));
}
