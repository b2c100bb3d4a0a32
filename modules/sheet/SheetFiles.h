// Writes a setup sheet: "<name>.html" with its pictures in "<name>-images/" beside it, and
// optionally a PDF printed by Qt (QTextDocument + QPdfWriter, no browser engine). Everything is
// written into a temporary folder first and renamed into place, so a failure leaves the old
// sheet (or nothing), never half of a new one. Needs a QGuiApplication (fonts).
#pragma once

#include "base/Result.h"
#include "document/SetupSheet.h"
#include "sheet/SheetHtml.h"

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
    SheetUnit unit = SheetUnit::Millimetre;
};

// Picture sizes in pixels: the part, and each operation's.
inline constexpr int kPartWidth = 720, kPartHeight = 480;
inline constexpr int kOperationWidth = 480, kOperationHeight = 320;

// A sheet written into temporary files beside its place (its HTML, pictures and PDF), not yet
// there: commit() renames them into place; what is not committed is removed when it goes. So
// the work can run on one thread and the decision whether the sheet is still wanted (cancelled,
// the job changed meanwhile) be taken on another. Move-only.
class StagedSheet {
public:
    StagedSheet(StagedSheet&& other) noexcept;
    StagedSheet& operator=(StagedSheet&&) = delete;
    StagedSheet(const StagedSheet&) = delete;
    ~StagedSheet();

    // Replaces the old sheet's pictures, then the HTML and the PDF. Once only.
    base::Status commit();

private:
    friend base::Result<StagedSheet> stageSetupSheet(const document::SetupSheet&, const SheetPicture&,
                                                     const SheetOutput&);
    StagedSheet() = default;
    void removeTemporaries();

    SheetOutput m_output;
    std::string m_temp, m_tempPdf, m_folder;  // temporary folder (HTML + pictures), PDF; picture folder's name
    bool m_done = false;
};

base::Result<StagedSheet> stageSetupSheet(const document::SetupSheet& sheet, const SheetPicture& pictures,
                                          const SheetOutput& output);

// stageSetupSheet, then commit.
base::Status writeSetupSheet(const document::SetupSheet& sheet, const SheetPicture& pictures,
                             const SheetOutput& output);

}  // namespace camwb::sheet
