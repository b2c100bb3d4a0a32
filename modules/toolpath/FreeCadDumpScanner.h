// The lexical layer of the FreeCAD dump reader: "Command <name> [ K:v ... ]" lines (a command may
// wrap onto following lines until its ']', as the dumper's long lines do in print) and the
// dumper's own "(...)" lines (which may wrap until their ')'), each part with its line and column.
#pragma once

#include "toolpath/ClBuilder.h"
#include "toolpath/ClText.h"

#include <string>
#include <string_view>
#include <vector>

namespace camwb::toolpath {

struct DumpParameter {
    char key = 0;  // upper-case letter
    double value = 0;
    TextPos pos;  // of the key
};

struct DumpEntry {
    enum class Kind { Command, Note };
    Kind kind = Kind::Command;
    int line = 0;      // first line
    std::string name;  // Command: "G1", "(comment)" or "" ([ ] alone); Note: the text inside ( )
    TextPos namePos;
    std::vector<DumpParameter> parameters;

    const DumpParameter* find(char key) const;
};

// All entries of a dump. Malformed lines ('[' without ']', a parameter that is not K:number, a
// line that is neither a Command nor a '(' line) are Errors with line and column.
base::Result<std::vector<DumpEntry>> scanFreeCadDump(const std::vector<std::string_view>& lines, const ClBuilder& out);

}  // namespace camwb::toolpath
