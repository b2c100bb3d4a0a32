// Tool libraries of other CAM systems read into ours: FreeCAD's ToolBit libraries (.fctl listing
// .fctb bit files) and Fusion 360's tool library JSON (.json, or a .tools file holding the JSON),
// the latter with its cutting data (presets: vc, fz, n, vf), which other importers drop. A
// malformed file is an error naming the file and the field; nothing is half-imported. Tools of a
// kind we do not model (probes, saws, thread mills, holders) are left out with a note.
#pragma once

#include "base/Result.h"
#include "document/ToolLibrary.h"

#include <string>
#include <vector>

namespace camwb::document {

struct ImportedTools {
    ToolLibrary library;
    std::vector<std::string> notes;  // what was left out or assumed, for the user
};

base::Result<ImportedTools> importFreeCadLibrary(const std::string& fctlPath);
base::Result<ImportedTools> importFusionLibrary(const std::string& path);
// By extension (.fctl FreeCAD, .tools Fusion) or, for .json, by content: ours, or Fusion's.
base::Result<ImportedTools> importToolLibrary(const std::string& path);

}  // namespace camwb::document
