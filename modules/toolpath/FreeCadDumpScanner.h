// The lexical layer of the FreeCAD dump reader: "Command <name> [ K:v ... ]" lines (a command may
// wrap onto following lines until its ']', as the dumper's long lines do in print) and the
// dumper's own "(...)" lines (which may wrap until their ')'), each part with its line and column.
// It hands out one entry at a time, so an import holds one line, not the file.
#pragma once

#include "base/LineReader.h"
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

// Reads the entries of a dump one after the other. Malformed lines ('[' without ']', a parameter
// that is not K:number, a line that is neither a Command nor a '(' line) are Errors with line and
// column.
class FreeCadDumpScanner {
public:
    FreeCadDumpScanner(base::LineReader& lines, const ClBuilder& out) : m_lines(lines), m_out(out) {}

    // The next entry into `entry`, whose storage is reused; false at the end of the dump.
    base::Result<bool> next(DumpEntry& entry);

private:
    base::Status note(std::string_view line, int lineNumber, int column, DumpEntry& entry);
    base::Status command(std::string_view line, int lineNumber, int column, DumpEntry& entry);
    base::Status parameters(DumpEntry& entry);

    base::LineReader& m_lines;
    const ClBuilder& m_out;
    PositionedText m_parameters;  // the text between '[' and ']', reused
};

}  // namespace camwb::toolpath
