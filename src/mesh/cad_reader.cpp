// STEP and IGES through OpenCASCADE: read, transferred to millimetres, tessellated by BRepMesh.
// The only translation unit of the mesh module that includes OpenCASCADE headers.

#include "cad_reader.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <filesystem>
#include <map>
#include <memory>

#include <BRepMesh_IncrementalMesh.hxx>
#include <BRep_Tool.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESControl_Reader.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_PrinterOStream.hxx>
#include <Poly_Triangulation.hxx>
#include <STEPControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <TopAbs_ShapeEnum.hxx>
#include <TopExp_Explorer.hxx>
#include <TopLoc_Location.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>

#include "mtcs/mesh/mesh_io.h"

namespace mtcs::mesh {

namespace {

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

// The file's shapes in millimetres (OpenCASCADE converts from the file's unit to its session
// unit, which is set to mm here).
TopoDS_Shape read_shape(const std::string& path) {
  const std::string ext = lower_extension(path);
  std::unique_ptr<XSControl_Reader> reader;
  if (ext == ".step" || ext == ".stp") reader = std::make_unique<STEPControl_Reader>();
  else reader = std::make_unique<IGESControl_Reader>();
  // The session unit exists once a reader has initialised its controller.
  if (!Interface_Static::SetCVal("xstep.cascade.unit", "MM"))
    throw MeshError(path + ": OpenCASCADE would not read in millimetres");
  if (reader->ReadFile(path.c_str()) != IFSelect_RetDone)
    throw MeshError("cannot read " + path + ": not a STEP or IGES file OpenCASCADE can parse");
  if (reader->TransferRoots() == 0) throw MeshError(path + ": no shape could be transferred from the file");
  const TopoDS_Shape shape = reader->OneShape();
  if (shape.IsNull()) throw MeshError(path + ": the file holds no shape");
  return shape;
}

}  // namespace

bool cad_available() { return true; }

TriangleMesh read_cad(const std::string& path) {
  // OpenCASCADE's transfer statistics would go to mtcs's stdout.
  Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
  try {
    const TopoDS_Shape shape = read_shape(path);
    const BRepMesh_IncrementalMesh mesher(shape, kCadChordalTolerance, false, kCadAngularTolerance, false);
    if (!mesher.IsDone()) throw MeshError(path + ": OpenCASCADE could not tessellate the shape");
    TriangleMesh m;
    // Neighbouring faces share their edges' nodes (the edge is discretised once), so equal
    // coordinates are the same vertex.
    std::map<std::array<double, 3>, int> index;
    std::size_t faces = 0;
    for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next(), ++faces) {
      const TopoDS_Face& face = TopoDS::Face(e.Current());
      TopLoc_Location where;
      const Handle(Poly_Triangulation) t = BRep_Tool::Triangulation(face, where);
      if (t.IsNull()) throw MeshError(path + ": face " + std::to_string(faces) + " could not be tessellated");
      const gp_Trsf placed = where.Transformation();
      std::vector<int> node(std::size_t(t->NbNodes()) + 1);
      for (int i = 1; i <= t->NbNodes(); ++i) {
        const gp_Pnt p = t->Node(i).Transformed(placed);
        const auto [it, added] = index.try_emplace({p.X(), p.Y(), p.Z()}, int(m.vertices.size()));
        if (added) m.vertices.emplace_back(p.X(), p.Y(), p.Z());
        node[std::size_t(i)] = it->second;
      }
      // A reversed face's triangles turn the other way round to face the solid's outside.
      const bool reversed = face.Orientation() == TopAbs_REVERSED;
      for (int k = 1; k <= t->NbTriangles(); ++k) {
        int a = 0, b = 0, c = 0;
        t->Triangle(k).Get(a, b, c);
        if (reversed) std::swap(b, c);
        const std::array<int, 3> tri{node[std::size_t(a)], node[std::size_t(b)], node[std::size_t(c)]};
        if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) continue;  // collapsed at a pole or seam
        m.triangles.push_back({tri[0], tri[1], tri[2]});
        if (m.triangles.size() > kMaxMeshTriangles)
          throw MeshError(path + ": more than " + std::to_string(kMaxMeshTriangles) + " triangles at a chordal tolerance of " +
                          std::to_string(kCadChordalTolerance) + " mm");
      }
    }
    if (m.triangles.empty()) throw MeshError(path + ": no faces to tessellate (a STEP part is a solid)");
    return m;
  } catch (const Standard_Failure& f) {
    throw MeshError("cannot read " + path + ": OpenCASCADE: " + std::string(f.GetMessageString()));
  }
}

}  // namespace mtcs::mesh
