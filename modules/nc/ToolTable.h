// A tool table in LinuxCNC's format (`T<n> P<pocket> D<diameter> Z<length> ;comment`, one tool
// a line), given to the interpreters through InterpretOptions: where a program names a tool but
// not its size, the table's diameter is the radius cutter compensation offsets by. Values in mm.
#pragma once

#include "base/Result.h"

#include <map>
#include <optional>
#include <string>
#include <string_view>

namespace camwb::nc {

struct ToolTableEntry {
    int number = 0;
    int pocket = 0;
    double diameterMm = 0;
    double lengthMm = 0;  // Z offset
    std::string comment;
};

class ToolTable {
public:
    // Adds or replaces the entry of `entry.number`.
    void set(const ToolTableEntry& entry) { m_tools[entry.number] = entry; }
    const ToolTableEntry* find(int number) const;
    // Half the diameter of tool `number`; nullopt when the table has no such tool.
    std::optional<double> radiusOf(int number) const;
    bool empty() const { return m_tools.empty(); }
    const std::map<int, ToolTableEntry>& tools() const { return m_tools; }

private:
    std::map<int, ToolTableEntry> m_tools;
};

// Parses a table; `fileName` names the file in errors ("file:line:column: message"). Each line
// holds words of a letter and a number (T P X Y Z A B C U V W D I J Q, T required, each at most
// once), then an optional ';' comment; empty and comment-only lines are skipped. A malformed
// number, an unknown letter, a missing T, a tool given twice or a negative diameter is an error.
base::Result<ToolTable> parseToolTable(std::string_view text, const std::string& fileName);
base::Result<ToolTable> readToolTable(const std::string& path);

}  // namespace camwb::nc
