// Writes a setup sheet: "<name>.html" with its pictures in "<name>-images/" beside it, and
// optionally a PDF printed by Qt (QTextDocument + QPdfWriter, no browser engine). Everything is
// written into a temporary folder first and renamed into place, so a failure leaves the old
// sheet (or nothing), never half of a new one. Needs a QGuiApplication (fonts).
#pragma once

#include "base/Result.h"
#include "document/SetupSheet.h"

#include <QImage>

#include <optional>
#include <string>

namespace camwb::toolpath {
class Toolpath;
}

namespace camwb::sheet {

class SheetPicture;

struct SheetOutput {
    std::string htmlPath;
    std::string pdfPath;                // empty: no PDF
    std::optional<QImage> partPicture;  // e.g. the 3D view's grab; none: the renderer draws it
};

// Picture sizes in pixels: the part, and each operation's.
inline constexpr int kPartWidth = 720, kPartHeight = 480;
inline constexpr int kOperationWidth = 480, kOperationHeight = 320;

base::Status writeSetupSheet(const document::SetupSheet& sheet, const SheetPicture& pictures,
                             const SheetOutput& output);

}  // namespace camwb::sheet
