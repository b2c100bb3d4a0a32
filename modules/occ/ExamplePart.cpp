// writeExamplePart: builds the teaching block with OCCT primitives and booleans and writes it as STEP.
#include "occ/ExamplePart.h"

#include <APIHeaderSection_MakeHeader.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRep_Tool.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <STEPControl_Writer.hxx>
#include <Standard_Failure.hxx>
#include <TCollection_HAsciiString.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Vertex.hxx>
#include <gp_Ax2.hxx>
#include <gp_Pnt.hxx>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <system_error>

namespace camwb::occ {
namespace {

// A box from (x0, y0, z0) to (x1, y1, z1) with its vertical edges rounded to `radius`.
TopoDS_Shape roundedBox(gp_Pnt lo, gp_Pnt hi, double radius)
{
    const TopoDS_Shape box = BRepPrimAPI_MakeBox(lo, hi).Shape();
    BRepFilletAPI_MakeFillet fillet(box);
    for (TopExp_Explorer it(box, TopAbs_EDGE); it.More(); it.Next()) {
        const TopoDS_Edge& edge = TopoDS::Edge(it.Current());
        const gp_Pnt a = BRep_Tool::Pnt(TopExp::FirstVertex(edge));
        const gp_Pnt b = BRep_Tool::Pnt(TopExp::LastVertex(edge));
        if (std::abs(a.X() - b.X()) < 1e-9 && std::abs(a.Y() - b.Y()) < 1e-9)
            fillet.Add(radius, edge);  // the explorer meets each edge twice; Add ignores repeats
    }
    return fillet.Shape();
}

TopoDS_Shape buildExamplePart()
{
    const TopoDS_Shape block = roundedBox(gp_Pnt(0, 0, 0), gp_Pnt(90, 60, 15), 8);
    // Tools reach 1 mm past the faces they open so the booleans see no coplanar faces.
    const TopoDS_Shape pocket = roundedBox(gp_Pnt(35 - 20, 30 - 12, 10), gp_Pnt(35 + 20, 30 + 12, 16), 5);
    const TopoDS_Shape hole = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(72, 30, -1), gp::DZ()), 5, 17).Shape();

    BRepAlgoAPI_Cut withPocket(block, pocket);
    if (!withPocket.IsDone())
        throw Standard_Failure("cutting the pocket failed");
    BRepAlgoAPI_Cut withHole(withPocket.Shape(), hole);
    if (!withHole.IsDone())
        throw Standard_Failure("cutting the hole failed");
    return withHole.Shape();
}

}  // namespace

base::Status writeExamplePart(const std::string& stepPath)
{
    try {
        const TopoDS_Shape part = buildExamplePart();
        STEPControl_Writer writer;
        if (writer.Transfer(part, STEPControl_AsIs) != IFSelect_RetDone)
            return base::makeError("could not convert the example part to STEP", stepPath);
        // Fixed header fields: regenerating the example gives a byte-identical file.
        APIHeaderSection_MakeHeader header(writer.Model());
        header.SetName(new TCollection_HAsciiString("example-block"));
        header.SetTimeStamp(new TCollection_HAsciiString("2024-01-01T00:00:00"));
        header.SetAuthorValue(1, new TCollection_HAsciiString("CAM Workbench"));
        header.SetOrganizationValue(1, new TCollection_HAsciiString("CAM Workbench"));
        header.SetOriginatingSystem(new TCollection_HAsciiString("CAM Workbench example generator"));
        header.SetPreprocessorVersion(new TCollection_HAsciiString("Open CASCADE 7.6"));
        header.SetAuthorisation(new TCollection_HAsciiString(""));

        // Write beside the target and rename, so a reader never sees half a file.
        const std::string temp = stepPath + ".tmp";
        if (writer.Write(temp.c_str()) != IFSelect_RetDone) {
            std::remove(temp.c_str());
            return base::makeError("could not write the file", stepPath);
        }
        std::error_code ec;
        std::filesystem::rename(temp, stepPath, ec);
        if (ec) {
            std::remove(temp.c_str());
            return base::makeError("could not write the file: " + ec.message(), stepPath);
        }
        return base::Status::success();
    } catch (const Standard_Failure& e) {
        return base::makeError(std::string("could not build the example part: ") + e.GetMessageString(), stepPath);
    }
}

}  // namespace camwb::occ
