#pragma once
// Where a test finds the checkout, its data and the mtcs binary. Defined in one generated file
// (tests/CMakeLists.txt) rather than passed as -D macros to every test file: no other compile
// command holds the checkout's path, so a fresh clone's build hits ccache (experiments/ci).

#include <string>

namespace mtcs_test {

const std::string& source_dir();     // the checkout
const std::string& test_data_dir();  // tests/data
const std::string& mtcs_binary();    // the built mtcs program

}  // namespace mtcs_test

#define MTCS_SOURCE_DIR (::mtcs_test::source_dir())
#define MTCS_TEST_DATA (::mtcs_test::test_data_dir())
#define MTCS_BINARY (::mtcs_test::mtcs_binary())
