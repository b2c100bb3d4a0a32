// The painter library's one exported symbol (SheetPainter.h, detail/PainterTable.h).
#include "sheet/detail/PainterTable.h"

#include "sheet/SheetFiles.h"
#include "sheet/SheetPicture.h"

#include <QGuiApplication>

#include <cstdlib>

namespace camwb::sheet {
namespace {

QtMessageHandler g_previousHandler = nullptr;

// The offscreen platform's note that XDG_RUNTIME_DIR is not set (it falls back to a folder of
// its own) says nothing about the sheet; stderr stays for the command's own messages.
void dropRuntimeDirNote(QtMsgType type, const QMessageLogContext& context, const QString& message)
{
    if (type == QtWarningMsg && message.startsWith(QStringLiteral("QStandardPaths: XDG_RUNTIME_DIR not set")))
        return;
    if (g_previousHandler)
        g_previousHandler(type, context, message);
}

void* makeApplication(int& argc, char** argv)
{
    // Fonts and images need a GUI application, a display does not: offscreen unless told otherwise.
    if (!std::getenv("QT_QPA_PLATFORM"))
        setenv("QT_QPA_PLATFORM", "offscreen", 1);
    g_previousHandler = qInstallMessageHandler(dropRuntimeDirNote);
    return new QGuiApplication(argc, argv);
}

void endApplication(void* application) { delete static_cast<QGuiApplication*>(application); }

base::Status write(const HeadlessSheet& sheet)
{
    const SheetPicture pictures(sheet.mesh, sheet.stock, sheet.program);
    SheetOutput output;
    output.htmlPath = sheet.htmlPath;
    output.pdfPath = sheet.pdfPath;
    output.unit = sheet.unit;
    return writeSetupSheet(sheet.sheet, pictures, output);
}

}  // namespace
}  // namespace camwb::sheet

extern "C" __attribute__((visibility("default"))) const camwb::sheet::detail::PainterTable* camwb_sheet_painter_table()
{
    using namespace camwb::sheet;
    static const detail::PainterTable table{detail::kPainterAbi, makeApplication, endApplication, write};
    return &table;
}
