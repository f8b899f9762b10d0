#pragma once
// Reading and writing triangle meshes: STL (ASCII and binary), OFF, OBJ and PLY through CGAL's
// I/O (the only place in mtcs that includes CGAL's I/O headers); writing STL, OBJ and PLY.

#include <array>
#include <cstdint>
#include <ostream>
#include <stdexcept>
#include <string>

#include "mtcs/mesh/triangle_mesh.h"

namespace mtcs::mesh {

class MeshError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Limits of read_mesh, checked before (file size) and after (counts) reading: a clear error
// rather than memory exhaustion or overflowing int indices.
inline constexpr std::uintmax_t kMaxMeshFileBytes = std::uintmax_t(2) << 30;  // 2 GiB
inline constexpr std::size_t kMaxMeshTriangles = 20'000'000;

// STEP and IGES parts are tessellated to within this distance of their surfaces (mm) and this
// angle between neighbouring facets' normals (radians): 50 facets around a 10 mm hole, far
// finer than any clearance mtcs checks.
inline constexpr double kCadChordalTolerance = 0.01;
inline constexpr double kCadAngularTolerance = 0.2;

// Reads a polygon mesh (faces with more than three corners are fanned into triangles, which is
// right for the convex faces CAD exporters write), or a STEP or IGES part (.step, .stp, .iges,
// .igs: tessellated as above where mtcs is built with OpenCASCADE). Throws MeshError naming the
// file.
TriangleMesh read_mesh(const std::string& path);
// Whether read_mesh takes STEP and IGES files in this build.
bool reads_cad_files();

// Binary STL.
void write_stl(const std::string& path, const TriangleMesh& mesh);

// Wavefront OBJ (vertices at 17 significant digits, faces 1-based).
void write_obj(std::ostream& out, const TriangleMesh& mesh);

// Per-face data for PLY: an RGB colour and a scalar, each empty or one per triangle. The
// scalar is written as the face property `quality`, which MeshLab reads as face quality;
// ParaView and MeshLab show the colours.
struct FaceAttributes {
  std::vector<std::array<unsigned char, 3>> colors;
  std::vector<double> quality;
};

// ASCII PLY with double coordinates and the per-face attributes given.
void write_ply(std::ostream& out, const TriangleMesh& mesh, const FaceAttributes& faces = {});

}  // namespace mtcs::mesh
