// STEP AP214 through OpenCASCADE's XDE (names survive into Creo, NX, SolidWorks, FreeCAD): the
// only translation unit of mtcs that includes OpenCASCADE headers.

#include "step_writer.h"

#include <filesystem>
#include <stdexcept>
#include <string>

#include <APIHeaderSection_MakeHeader.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_PrinterOStream.hxx>
#include <STEPCAFControl_Writer.hxx>
#include <Standard_Failure.hxx>
#include <TCollection_HAsciiString.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <gp_Ax2.hxx>

#include "mtcs/report/layout_export.h"
#include "mtcs/version.h"

namespace mtcs::report {

bool step_available() { return true; }

void write_step(const std::string& path, const mold::Layout& layout) {
  try {
    // OpenCASCADE's transfer statistics would go to mtcs's stdout.
    Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
    Handle(TDocStd_Document) doc;
    XCAFApp_Application::GetApplication()->NewDocument("MDTV-XCAF", doc);
    const Handle(XCAFDoc_ShapeTool) shapes = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
    for (const mold::Bore& b : layout.bores) {
      const geometry::Vec3 axis = b.hole.p1 - b.hole.p0;
      if (axis.norm() == 0) continue;  // as bores.stl: no solid of a zero-length hole
      const gp_Ax2 frame(gp_Pnt(b.hole.p0.x(), b.hole.p0.y(), b.hole.p0.z()), gp_Dir(axis.x(), axis.y(), axis.z()));
      const TopoDS_Shape solid = BRepPrimAPI_MakeCylinder(frame, b.hole.radius, axis.norm()).Shape();
      // A blind bore's name says its insert: the shop fits a baffle or a bubbler there.
      const std::string name = is_blind(b.kind) ? b.name() + " " + mold::to_string(b.kind) : b.name();
      TDataStd_Name::Set(shapes->AddShape(solid, Standard_False), name.c_str());
    }
    Interface_Static::SetCVal("write.step.schema", "AP214IS");
    Interface_Static::SetCVal("write.step.unit", "MM");
    Interface_Static::SetCVal("write.step.product.name", "mtcs cooling bores");
    STEPCAFControl_Writer writer;
    writer.SetNameMode(Standard_True);
    if (!writer.Transfer(doc, STEPControl_AsIs)) throw std::runtime_error("STEP: OpenCASCADE could not transfer the bores");
    // The header's FILE_NAME says who wrote the file (OpenCASCADE's default author is 'Unknown').
    APIHeaderSection_MakeHeader header(writer.ChangeWriter().Model());
    header.SetAuthorValue(1, new TCollection_HAsciiString("mtcs"));
    header.SetOrganizationValue(1, new TCollection_HAsciiString("mtcs cooling bores"));
    header.SetOriginatingSystem(new TCollection_HAsciiString((std::string(kProgram) + " (OpenCASCADE)").c_str()));
    header.SetAuthorisation(new TCollection_HAsciiString(""));
    header.SetName(new TCollection_HAsciiString(std::filesystem::path(path).filename().string().c_str()));
    // Beside the target, then renamed: nothing half-written under the name asked for.
    const std::string tmp = path + ".tmp";
    if (writer.Write(tmp.c_str()) != IFSelect_RetDone) {
      std::filesystem::remove(tmp);
      throw std::runtime_error("STEP: cannot write " + tmp);
    }
    std::filesystem::rename(tmp, path);
  } catch (const Standard_Failure& e) {
    throw std::runtime_error(std::string("STEP (OpenCASCADE): ") + e.GetMessageString());
  }
}

}  // namespace mtcs::report
