// Mesh files on mutated input (OFF, ASCII STL, OBJ): each read ends in a mesh or a MeshError;
// a mesh that reads goes through validation, and when it bounds a solid, through a clearance
// query. Nothing crashes or escapes. Run under the sanitizer build too.

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <random>
#include <unistd.h>

#include "mtcs/mesh/bvh.h"
#include "mtcs/mesh/mesh_check.h"
#include "mtcs/mesh/mesh_io.h"
#include "fuzz_mutate.h"
#include "support/scratch_file.h"

TEST_CASE("mesh reader survives mutated OFF, STL and OBJ input", "[mesh][fuzz]") {
  // A tetrahedron, outward, in each format.
  const std::vector<std::pair<std::string, std::string>> seeds{
      {".off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"},
      {".stl",
       "solid t\nfacet normal 0 0 -1\nouter loop\nvertex 0 0 0\nvertex 0 1 0\nvertex 1 0 0\nendloop\nendfacet\n"
       "facet normal 0 -1 0\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 0 1\nendloop\nendfacet\n"
       "facet normal -1 0 0\nouter loop\nvertex 0 0 0\nvertex 0 0 1\nvertex 0 1 0\nendloop\nendfacet\n"
       "facet normal 1 1 1\nouter loop\nvertex 1 0 0\nvertex 0 1 0\nvertex 0 0 1\nendloop\nendfacet\nendsolid t\n"},
      {".obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"}};
  const std::string alphabet = "0123456789 .-+eE\n\tfv/#OFsolidnrmaxtp";
  std::mt19937_64 rng(31);
  int read = 0, solid = 0, rejected = 0;
  for (const auto& [ext, seed] : seeds) {
    const auto path = mtcs_test::scratch_dir("fuzz_mesh") / ("input" + ext);
    for (int i = 0; i < 600; ++i) {
      const std::string s = mtcs_test::mutate(seed, alphabet, rng, 5, 6);
      std::ofstream(path, std::ios::binary) << s;
      try {
        const mtcs::mesh::TriangleMesh m = mtcs::mesh::read_mesh(path.string());
        ++read;
        const auto check = mtcs::mesh::check_mesh(m);
        if (!check.ok()) {
          CHECK_FALSE(check.message().empty());
          continue;
        }
        ++solid;
        const mtcs::mesh::TriangleBvh bvh(m);
        const auto c = mtcs::mesh::cylinder_clearance(bvh, {{-1, -1, -1}, {2, 2, 2}, 0.1}, 10.0);
        CHECK(c.distance >= 0);
      } catch (const mtcs::mesh::MeshError&) {
        ++rejected;
      }
    }
    std::filesystem::remove(path);
  }
  CHECK(read > 0);
  CHECK(solid > 0);
  CHECK(rejected > 0);
}
