// The setup sheet for a program that does not link Qt Gui (camwb-cli): its pictures and PDF are
// drawn by the painter library (libcamwb_sheet_painter.so: SheetPicture and SheetFiles over Qt
// Gui), loaded when a sheet is written, so that the program's other commands start without Qt
// Gui's thirty libraries. The GUI, which links Qt Gui anyway, calls SheetFiles.h directly.
#pragma once

#include "base/Result.h"
#include "document/SetupSheet.h"
#include "occ/DisplayMesh.h"
#include "sheet/SheetHtml.h"

#include <memory>
#include <optional>
#include <string>

namespace camwb::toolpath {
class Toolpath;
}

namespace camwb::sheet {

// writeSetupSheet()'s input (SheetFiles.h), its pictures drawn from the model's mesh, the stock
// and the program (SheetPicture.h).
struct HeadlessSheet {
    const document::SetupSheet& sheet;
    occ::DisplayMesh mesh;
    std::optional<base::Box3> stock;
    const toolpath::Toolpath& program;
    std::string htmlPath;
    std::string pdfPath;  // empty: no PDF
    SheetUnit unit = SheetUnit::Millimetre;
};

// The application a sheet is drawn in: a GUI one (fonts, images) on the offscreen platform
// unless QT_QPA_PLATFORM names another. Made by the painter library before anything else; it
// ends when the handle is destroyed. No Qt type shows here: the program links no Qt.
using SheetApplication = std::unique_ptr<void, void (*)(void*)>;
base::Result<SheetApplication> sheetApplication(int& argc, char** argv);

// Needs sheetApplication()'s application.
base::Status writeHeadlessSheet(const HeadlessSheet& sheet);

}  // namespace camwb::sheet
