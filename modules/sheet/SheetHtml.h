// The setup sheet as HTML: tables an operator reads at the machine (tools first, then stock and
// work zero, machine and post, operations with their pictures, what the simulator verified).
// Qt-free text; the same HTML is shown in a browser and printed to PDF by Qt (SheetFiles.h), so
// it keeps to what QTextDocument renders (table attributes, no CSS layout).
#pragma once

#include "document/SetupSheet.h"

#include <string>
#include <vector>

namespace camwb::sheet {

struct SheetImage {
    std::string file;  // relative to the HTML file ("sheet-images/part.png"); empty: none
    int width = 0, height = 0;
};

struct SheetImages {
    SheetImage part;
    std::vector<SheetImage> operations;  // job order; missing entries: no picture
};

// What lengths and feeds are shown in: the job's mm and mm/min, or inch and in/min (the
// window's display unit). Only the text changes; the sheet's data stays in mm.
enum class SheetUnit { Millimetre, Inch };

std::string sheetHtml(const document::SetupSheet& sheet, const SheetImages& images,
                      SheetUnit unit = SheetUnit::Millimetre);

// `text` with & < > " escaped for HTML text and attribute values.
std::string escapeHtml(const std::string& text);

// "7 min 12.3 s" (or "42.0 s" under a minute).
std::string formatDuration(double seconds);

}  // namespace camwb::sheet
