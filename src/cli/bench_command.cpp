// mtcs bench: the benchmarks live in their own program, mtcs-bench, so that the peers they
// measure against (FCL, pagmo, CGAL's intersection test, NLopt's ISRES) stay out of this binary.
// `mtcs bench ARGS` runs the mtcs-bench beside this binary with ARGS and returns its exit code.

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "mtcs/cli/commands.h"

namespace mtcs::cli {

std::string bench_program_path() {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ((ec ? std::filesystem::path(".") : self.parent_path()) / "mtcs-bench").string();
}

int run_bench_program(int argc, char** argv) {
  const std::string program = bench_program_path();
  std::vector<char*> args{const_cast<char*>(program.c_str())};
  for (int i = 0; i < argc; ++i) args.push_back(argv[i]);
  args.push_back(nullptr);
  ::execv(program.c_str(), args.data());
  const int err = errno;  // execv returns only on failure
  std::cerr << "mtcs: bench: cannot run " << program << ": " << std::strerror(err)
            << "\n(a separate program with its peers FCL and pagmo: bash scripts/setup.sh installs them, "
               "then cmake -S . -B build -DMTCS_BUILD_BENCH=ON && cmake --build build --target mtcs-bench)\n";
  return err == ENOENT ? 127 : 126;
}

}  // namespace mtcs::cli
