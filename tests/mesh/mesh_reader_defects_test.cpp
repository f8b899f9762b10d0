// Mesh files on which CGAL's readers ran into undefined behaviour, found by the libFuzzer
// targets (fuzz/, experiments/fuzz/README.md), and the reader's size limits: each is refused
// with a MeshError naming the file and line, before CGAL reads it.

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "mtcs/mesh/mesh_io.h"
#include "support/thrown_by.h"
#include "support/scratch_file.h"
#include "support/paths.h"

using mtcs::mesh::MeshError;
using mtcs::mesh::read_mesh;
namespace fs = std::filesystem;

namespace {

std::string write(const std::string& name, const std::string& text) {
  const fs::path dir = mtcs_test::scratch_dir("mesh_defects");
  std::ofstream(dir / name, std::ios::binary) << text;
  return (dir / name).string();
}

std::string error_of(const std::string& path) {
  return mtcs_test::thrown_by<MeshError>([&] { read_mesh(path); }, path).what();
}

const std::string kTetraVertices = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n";

}  // namespace

// fuzz_mesh_off, crash-cbfd5a7b: CGAL's File_scanner_OFF casts a face's index from double to
// size_t, undefined behaviour for -47 (UBSan: "-47 is outside the range of representable values").
TEST_CASE("mesh reader defect: a negative face index in OFF is refused at its line", "[mesh][fuzz-defect]") {
  const auto path = write("negative.off", "OFF\n4 4 0\n" + kTetraVertices + "3 0 2 1\n3 0 1 3\n3 0 -47 2\n3 1 2 3\n");
  const std::string e = error_of(path);
  CHECK_THAT(e, Catch::StartsWith(path + ":9: face 2 refers to vertex -47"));
  // A negative corner count and an index past the vertices, likewise.
  CHECK_THAT(error_of(write("size.off", "OFF\n4 1 0\n" + kTetraVertices + "-3 0 1 2\n")), Catch::Contains(":7: face 0 has a corner count"));
  CHECK_THAT(error_of(write("past.off", "OFF\n4 1 0\n" + kTetraVertices + "3 0 1 1e300\n")), Catch::Contains("not one of the 4 vertices"));
  // Comments and counts on the keyword's line keep the line numbers right.
  CHECK_THAT(error_of(write("comment.off", "# made by hand\nOFF 4 1 0\n# vertices\n" + kTetraVertices + "\n3 0 1 -2\n")),
             Catch::Contains(":9: face 0 refers to vertex -2"));
}

// fuzz_mesh_ply, crash-08c18110: CGAL's PLY_reader adds a property to elements.back() of an
// empty list (UBSan: "applying non-zero offset to null pointer") when a property comes first.
TEST_CASE("mesh reader defect: a PLY property before any element is refused at its line", "[mesh][fuzz-defect]") {
  const auto path = write("orphan.ply", "ply\nformat ascii 1.0\nproperty float x\nelement vertex 1\nend_header\n0\n");
  CHECK_THAT(error_of(path), Catch::StartsWith(path + ":3: a property before any element"));
}

TEST_CASE("mesh reader: binary and n-dimensional OFF are refused as unsupported", "[mesh][fuzz-defect]") {
  CHECK_THAT(error_of(write("binary.off", std::string("OFF BINARY\n\0\0\0\4", 15))), Catch::Contains("binary OFF is not supported"));
  CHECK_THAT(error_of(write("ndim.off", "nOFF\n3\n4 1 0\n")), Catch::Contains("variant nOFF"));
  CHECK_THAT(error_of(write("count.off", "OFF\n4 -1 0\n")), Catch::Contains("count -1 is out of range"));
}

TEST_CASE("mesh reader: a file beyond the 2 GiB limit is refused before it is read", "[mesh][bad-numbers]") {
  const auto path = write("huge.stl", "");
  fs::resize_file(path, mtcs::mesh::kMaxMeshFileBytes + 1);  // sparse: no disk, no time
  CHECK_THAT(error_of(path), Catch::Contains("more than the 2147483648 bytes a mesh file may have"));
  fs::remove(path);
}

TEST_CASE("mesh reader: a plain tetrahedron still reads after the checks", "[mesh][fuzz-defect]") {
  const auto m = read_mesh(write("tetra.off", "OFF\n# comment\n4 4 0\n" + kTetraVertices + "3 0 2 1\n3 0 1 3 # c\n3 0 3 2\n3 1 2 3\n"));
  CHECK(m.vertices.size() == 4);
  CHECK(m.triangles.size() == 4);
  CHECK(m.triangles[1] == std::array<int, 3>{0, 1, 3});
}

// fuzz_mesh_off, crash-55f00afc: "OFF\nBINARY" followed by bytes: CGAL's header reader doubled
// a garbage edge count in int (UBSan: signed integer overflow, 2 * 2117405237).
TEST_CASE("mesh reader defect: BINARY glued to garbage after OFF is refused, no overflow", "[mesh][fuzz-defect]") {
  CHECK_THAT(error_of(write("glued.off", "OFF\nBINARY\xb5~5\n52\n")), Catch::Contains(":2: binary OFF is not supported"));
  CHECK_THAT(error_of(write("edges.off", "OFF\n4 4 2117405237\n")), Catch::Contains("count 2117405237 is out of range"));
}

// fuzz_mesh_ply, crash-48ea8ea7: "property uint16 y" of a vertex: CGAL's PLY reader reads
// coordinates as float or double only and dereferenced a null pointer.
TEST_CASE("mesh reader defect: an integer vertex coordinate in PLY is refused at its line", "[mesh][fuzz-defect]") {
  const auto path = write("int.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty double x\nproperty uint16 y\n"
                                     "property double z\nend_header\n0 0 0\n");
  CHECK_THAT(error_of(path), Catch::StartsWith(path + ":5: vertex property y must be float or double, not uint16"));
}

// fuzz_mesh_ply, timeout-*: "element vertex -48": CGAL's PLY reader took the count as 2^64 - 48
// and read on past the end of the file (a hang).
TEST_CASE("mesh reader defect: a negative PLY element count is refused at its line, no hang", "[mesh][fuzz-defect]") {
  const auto path = write("negative.ply", "ply\nformat binary_little_endian 1.0\nelement vertex -48\nproperty float x\nend_header\n");
  CHECK_THAT(error_of(path), Catch::StartsWith(path + ":3: element vertex has the count '-48'"));
  CHECK_THAT(error_of(write("huge.ply", "ply\nformat ascii 1.0\nelement face 99999999999\nend_header\n")), Catch::Contains("'99999999999'"));
}

// fuzz_mesh_off, crash-(round 3): "OFF 0\n4 5-1(3": counts glued to the first face; CGAL reads
// 0 4 5 as numbers, then the face "-1(3" casts -1 to size_t.
TEST_CASE("mesh reader defect: a negative corner count after glued counts is refused", "[mesh][fuzz-defect]") {
  CHECK_THAT(error_of(write("glued_counts.off", "OFF 0\n4 5-1(3 2.5\n")), Catch::Contains("face 0 has a corner count"));
}

// fuzz_mesh_off, crash-4734c32a: "OFF]" then "BINARY": CGAL took the keyword and converted a
// garbage count of 4.6e9 to int (UBSan). And slow-unit-092f223d: "OFF\n35 17046664" in a
// 100-byte file kept CGAL reading 17 million faces past the end for 10 s.
TEST_CASE("mesh reader defect: an OFF keyword with garbage and counts beyond the file are refused", "[mesh][fuzz-defect]") {
  const auto path = write("bracket.off", "OFF]\nBINARY\n");
  CHECK_THAT(error_of(path), Catch::StartsWith(path + ":1: not an OFF file: it starts with 'OFF]'"));
  CHECK_THAT(error_of(write("promise.off", "OFF\n35 17046664 0\n0 0 0\n")),
             Catch::Contains("promises 35 vertices and 17046664 faces, more than a file of"));
  CHECK_THAT(error_of(write("promise.ply", "ply\nformat ascii 1.0\nelement vertex 1000\nend_header\n")),
             Catch::Contains("element vertex has the count '1000'"));
}

// fuzz_mesh_off, crash-99b86e8e: a COFF vertex line too short for its colour: CGAL's
// File_scanner_OFF::scan_color read past its entries (ASan: heap-buffer-overflow).
TEST_CASE("mesh reader defect: the OFF variants with colours or normals are refused", "[mesh][fuzz-defect]") {
  const auto path = write("coff.off", "COFF\n2 6\n3 1 6\n50 52.5 3\n");
  CHECK_THAT(error_of(path), Catch::StartsWith(path + ":1: the OFF variant COFF is not supported: plain OFF only"));
  for (const std::string variant : {"NOFF", "STOFF", "4OFF", "CNOFF"})
    CHECK_THAT(error_of(write("variant.off", variant + "\n4 4 0\n")), Catch::Contains("variant " + variant));
}

// fuzz_mesh_ply, oom (round 5): "property list int32 int vertex_indices": CGAL allocated a list
// as long as a 32-bit count said (malloc of 4.7 GB from a 1 kB file).
TEST_CASE("mesh reader defect: a PLY list counted in 32 bits is refused at its line", "[mesh][fuzz-defect]") {
  const auto path = write("list32.ply", "ply\nformat ascii 1.0\nelement face 1\nproperty list int32 int vertex_indices\nend_header\n3 0 1 2\n");
  CHECK_THAT(error_of(path), Catch::StartsWith(path + ":4: a list counted in int32"));
}

// fuzz_mesh_ply, crash-48a04839 (smoke run): "property fproperty double x": the property's name
// is its last word (x) and its type the garbage "fproperty": the null dereference of crash-48ea8ea7.
TEST_CASE("mesh reader defect: a vertex coordinate of an unknown type is refused", "[mesh][fuzz-defect]") {
  const auto path = write("garbage_type.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty fproperty double x\n"
                                              "property double y\nproperty double z\nend_header\n0 0 0\n");
  CHECK_THAT(error_of(path), Catch::StartsWith(path + ":4: vertex property x must be float or double, not fproperty"));
}

// fuzz_mesh_ply, crash-9899519a (long round, 2026-11-25; kept as
// tests/data/meshes/fuzz_crash_ply_list_z.ply): a vertex's z declared as a list ("property list
// uchar double z") after x and y twice: CGAL reads z through a number reader of another type
// (UBSan: "member call on null pointer of type PLY_read_typed_number<float>").
TEST_CASE("mesh reader defect: a PLY vertex coordinate declared as a list, or twice, is refused", "[mesh][fuzz-defect]") {
  const std::string artifact = MTCS_TEST_DATA + "/meshes/fuzz_crash_ply_list_z.ply";
  CHECK_THAT(error_of(artifact), Catch::StartsWith(artifact + ":7: property x of element vertex is declared twice"));
  const std::string head = "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n";
  const auto list = write("list_z.ply", head + "property list uchar double z\nend_header\n0 0 1 0\n");
  CHECK_THAT(error_of(list), Catch::StartsWith(list + ":6: vertex property z must be float or double, not a list"));
  const auto twice = write("twice.ply", head + "property float z\nproperty double y\nend_header\n0 0 0 0\n");
  CHECK_THAT(error_of(twice), Catch::StartsWith(twice + ":7: property y of element vertex is declared twice"));
}

// fuzz_mesh_ply, crash-116d2d1a (long round 2, after the fix above; kept as
// tests/data/meshes/fuzz_crash_ply_integer_y.ply): "property uint16 y ist uchar ... 48": CGAL
// names a property by the word after its type (y), not the line's last word (48), which the
// check read: an integer y again (the null dereference of crash-48ea8ea7).
TEST_CASE("mesh reader defect: a PLY property is named by the word after its type, as CGAL reads it", "[mesh][fuzz-defect]") {
  const std::string artifact = MTCS_TEST_DATA + "/meshes/fuzz_crash_ply_integer_y.ply";
  CHECK_THAT(error_of(artifact), Catch::StartsWith(artifact + ":6: vertex property y must be float or double, not uint16"));
  const auto path = write("trailing.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                                          "property uint16 y garbage\nproperty float z\nend_header\n0 0 0\n");
  CHECK_THAT(error_of(path), Catch::StartsWith(path + ":5: vertex property y must be float or double, not uint16"));
  // A list: the name follows the count's and the items' types.
  const auto list = write("list_y.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                                        "property list uchar float y trailing\nproperty float z\nend_header\n0 1 0 0\n");
  CHECK_THAT(error_of(list), Catch::StartsWith(list + ":5: vertex property y must be float or double, not a list"));
}

// Fuzz crash #14 (mesh_ply, crash-2734376c, input kept as
// tests/data/meshes/fuzz_crash_ply_vertices_int8_z.ply): "element vertices 16" with "property int8
// z": CGAL takes an element named "vertices" for the vertex element, so the integer z met its
// float reader (the null dereference of #5) past a check that looked at "vertex" only.
TEST_CASE("mesh reader defect: a PLY element named vertices has its coordinates checked like vertex", "[mesh][fuzz-defect]") {
  const std::string artifact = MTCS_TEST_DATA + "/meshes/fuzz_crash_ply_vertices_int8_z.ply";
  CHECK_THAT(error_of(artifact), Catch::Contains("vertex property z must be float or double, not int8"));
  const auto path = write("vertices.ply", "ply\nformat ascii 1.0\nelement vertices 1\nproperty float x\n"
                                          "property float y\nproperty short z\nend_header\n0 0 0\n");
  CHECK_THAT(error_of(path), Catch::StartsWith(path + ":6: vertex property z must be float or double, not short"));
}

// Fuzz crash #15 (mesh_ply, crash-630daee5, input kept as
// tests/data/meshes/fuzz_crash_ply_halfedge_source.ply): CGAL reads every item of an element named
// "halfedge" as an unsigned int "source" and "target" whatever the header declares; a halfedge
// element without them (or with another type) met a missing reader (UBSan: member call on null
// pointer of type PLY_read_typed_number<unsigned int>, PLY_reader.h:387).
TEST_CASE("mesh reader defect: a PLY halfedge element needs uint source and target", "[mesh][fuzz-defect]") {
  const std::string artifact = MTCS_TEST_DATA + "/meshes/fuzz_crash_ply_halfedge_source.ply";
  CHECK_THAT(error_of(artifact), Catch::Contains("element halfedge needs the property source as uint"));
  const std::string tetra = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                            "property float z\nelement face 1\nproperty list uchar int vertex_indices\n";
  const auto typed = write("halfedge_int.ply", tetra + "element halfedge 1\nproperty int source\nproperty uint target\n"
                                                       "end_header\n" + kTetraVertices + "3 0 1 2\n0 1\n");
  CHECK_THAT(error_of(typed), Catch::StartsWith(typed + ":9: element halfedge needs the property source as uint (uint32), not int"));
  const auto missing = write("halfedge_no_target.ply", tetra + "element halfedge 1\nproperty uint32 source\n"
                                                               "end_header\n" + kTetraVertices + "3 0 1 2\n0\n");
  CHECK_THAT(error_of(missing), Catch::StartsWith(missing + ":9: element halfedge needs the property target as uint (uint32), not declared"));
  // With both as CGAL reads them, and with none when the element is empty, the mesh still reads.
  const auto good = write("halfedge_good.ply", tetra + "element halfedge 1\nproperty uint source\nproperty uint32 target\n"
                                                       "end_header\n" + kTetraVertices + "3 0 1 2\n0 1\n");
  CHECK(read_mesh(good).triangles.size() == 1);
  const auto empty = write("halfedge_empty.ply", tetra + "element halfedge 0\nproperty float u\nend_header\n" + kTetraVertices + "3 0 1 2\n");
  CHECK(read_mesh(empty).triangles.size() == 1);
}

// The reader's side of fuzz crash #16: a path the file system refuses to look up is a MeshError.
TEST_CASE("mesh reader defect: a file name too long for the file system is a MeshError", "[mesh][fuzz-defect]") {
  const std::string path = mtcs_test::scratch_dir("mesh_defects") / (std::string(300, 'b') + ".off");
  CHECK_THAT(error_of(path), Catch::Contains("mesh file not found") && Catch::Contains("too long"));
}
