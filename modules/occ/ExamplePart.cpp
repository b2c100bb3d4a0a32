// writeExamplePart: builds the teaching block with OCCT primitives and booleans and writes it as STEP.
#include "occ/detail/ModelData.h"

#include "occ/detail/DataExchangeLock.h"
#include "occ/detail/PartBuilders.h"

#include <APIHeaderSection_MakeHeader.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <STEPControl_Writer.hxx>
#include <Standard_Failure.hxx>
#include <TCollection_HAsciiString.hxx>

#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>
#include <system_error>
#include <utility>

namespace camwb::occ {
namespace {

TopoDS_Shape buildExamplePart()
{
    using parts::cut, parts::drilledHole, parts::roundedBox, parts::verticalCylinder;
    TopoDS_Shape part = roundedBox(gp_Pnt(0, 0, 0), gp_Pnt(90, 60, 15), 8);
    // Tools reach 1 mm past the faces they open so the booleans see no coplanar faces. The pocket
    // tool has the island cut out of it, so the island keeps the block's top at Z 15.
    const TopoDS_Shape pocket = roundedBox(gp_Pnt(33 - 22, 30 - 18, 10), gp_Pnt(33 + 22, 30 + 18, 16), 6);
    part = cut(part, cut(pocket, verticalCylinder(33, 30, 5, 9, 17), "the island"), "the pocket");
    part = cut(part, verticalCylinder(72, 30, 5, -1, 16), "the through hole");
    // Blind holes concentric with the R8 corners: 5.5 mm of wall to the outside, about 5 mm to the
    // pocket; drilled, so with a 118° drill's point below their full depth (what the simulator
    // compares the drilled part with).
    for (const auto& [x, y] : {std::pair{8.0, 8.0}, {82.0, 8.0}, {82.0, 52.0}, {8.0, 52.0}})
        part = cut(part, drilledHole(x, y, 2.5, 7, 16, 118), "a drilled hole");
    return part;
}

}  // namespace

namespace detail {

base::Status writeStep(const std::function<TopoDS_Shape()>& build, const char* name, const std::string& stepPath)
{
    try {
        const TopoDS_Shape part = build();
        const std::lock_guard<std::mutex> lock(dataExchangeMutex());
        STEPControl_Writer writer;
        if (writer.Transfer(part, STEPControl_AsIs) != IFSelect_RetDone)
            return base::makeError("could not convert the example part to STEP", stepPath);
        // Fixed header fields: regenerating the example gives a byte-identical file.
        APIHeaderSection_MakeHeader header(writer.Model());
        header.SetName(new TCollection_HAsciiString(name));
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

}  // namespace detail

base::Status occt::writeExamplePart(const std::string& stepPath)
{
    return detail::writeStep(buildExamplePart, "example-block", stepPath);
}

}  // namespace camwb::occ
