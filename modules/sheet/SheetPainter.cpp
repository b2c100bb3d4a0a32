#include "sheet/SheetPainter.h"

#include "base/PluginLibrary.h"
#include "sheet/detail/PainterTable.h"

namespace camwb::sheet {
namespace {

base::Result<const detail::PainterTable*> painter()
{
    static const base::Result<const detail::PainterTable*> loaded = base::loadPlugin<detail::PainterTable>(
        {"the setup sheet's painter", "libcamwb_sheet_painter.so draws the sheet's pictures and prints its PDF",
         "CAMWB_SHEET_PAINTER", CAMWB_SHEET_PAINTER_FROM_BINDIR, CAMWB_SHEET_PAINTER_BUILT},
        detail::kPainterEntryPoint, detail::kPainterAbi);
    return loaded;
}

}  // namespace

base::Result<SheetApplication> sheetApplication(int& argc, char** argv)
{
    const base::Result<const detail::PainterTable*> loaded = painter();
    if (!loaded)
        return loaded.error();
    return SheetApplication(loaded.value()->makeApplication(argc, argv), loaded.value()->endApplication);
}

base::Status writeHeadlessSheet(const HeadlessSheet& sheet)
{
    const base::Result<const detail::PainterTable*> loaded = painter();
    if (!loaded)
        return base::makeError(loaded.error().message, sheet.htmlPath);
    return loaded.value()->write(sheet);
}

}  // namespace camwb::sheet
