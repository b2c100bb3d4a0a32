// The painter library's entry points (SheetPainter.h): its one exported C symbol returns this.
#pragma once

#include "sheet/SheetPainter.h"

namespace camwb::sheet::detail {

struct PainterTable {
    int abi = 0;                                       // kPainterAbi when library and program were built together
    void* (*makeApplication)(int& argc, char** argv);  // a QGuiApplication
    void (*endApplication)(void* application);         // deletes what makeApplication made
    base::Status (*write)(const HeadlessSheet& sheet);
};

// Raise whenever PainterTable, HeadlessSheet or the types they hold change.
inline constexpr int kPainterAbi = 2;
inline constexpr const char* kPainterEntryPoint = "camwb_sheet_painter_table";

}  // namespace camwb::sheet::detail
