// The painter library's entry points (SheetPainter.h): its one exported C symbol returns this.
#pragma once

#include "sheet/SheetPainter.h"

namespace camwb::sheet::detail {

struct PainterTable {
    int abi = 0;  // kPainterAbi when library and program were built together
    QCoreApplication* (*makeApplication)(int& argc, char** argv);
    base::Status (*write)(const HeadlessSheet& sheet);
};

// Raise whenever PainterTable, HeadlessSheet or the types they hold change.
inline constexpr int kPainterAbi = 1;
inline constexpr const char* kPainterEntryPoint = "camwb_sheet_painter_table";

}  // namespace camwb::sheet::detail
