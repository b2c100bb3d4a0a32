// The lexical layer of the FreeCAD dump reader: "Command <name> [ K:v ... ]" lines (a command may
// wrap onto following lines until its ']', as the dumper's long lines do in print) and the
// dumper's own "(...)" lines (which may wrap until their ')'), each part with its line and column.
// It hands out one entry at a time, so an import holds one line, not the file.
#pragma once

#include "base/LineReader.h"
#include "toolpath/ClBuilder.h"
#include "toolpath/ClText.h"

#include <array>
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

    const DumpParameter* find(char key) const
    {
        const int at = key >= 'A' && key <= 'Z' ? m_index[key - 'A'] : -1;
        return at < 0 ? nullptr : &parameters[static_cast<std::size_t>(at)];
    }
    void add(const DumpParameter& parameter)
    {
        m_index[static_cast<std::size_t>(parameter.key - 'A')] = static_cast<signed char>(parameters.size());
        parameters.push_back(parameter);
    }
    void clearParameters();

private:
    std::array<signed char, 26> m_index = filledIndex();  // by letter: position in parameters, -1: none

    static constexpr std::array<signed char, 26> filledIndex()
    {
        std::array<signed char, 26> index{};
        index.fill(-1);
        return index;
    }
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
    // Where character i of the parameter text sits: in `text` when the parameters were joined
    // from several lines, else on `line` from `column` on.
    struct Where {
        const PositionedText* text;
        int line;
        int column;
        TextPos operator()(std::size_t i) const
        {
            return text ? text->position(i) : TextPos{line, column + static_cast<int>(i)};
        }
    };
    base::Status parameters(std::string_view text, Where where, DumpEntry& entry);

    base::LineReader& m_lines;
    const ClBuilder& m_out;
    PositionedText m_parameters;  // the text between '[' and ']' joined from several lines, reused
};

}  // namespace camwb::toolpath
