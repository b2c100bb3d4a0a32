#include "nc/tools/ErrorRecords.h"

#include <algorithm>
#include <set>
#include <utility>

namespace camwb::nc {

std::vector<bool> recordsInError(const toolpath::Toolpath& program, const InterpretResult& result)
{
    // (file index, line) of every error; a diagnostic without a file is the main program's.
    std::set<std::pair<int, int>> errorLines;
    for (const Diagnostic& d : result.diagnostics) {
        if (d.severity != Severity::Error)
            continue;
        int index = 0;
        if (!d.file.empty()) {
            const auto file = std::find(result.files.begin(), result.files.end(), d.file);
            if (file == result.files.end())
                continue;  // a program that was never read: no record of it
            index = static_cast<int>(file - result.files.begin());
        }
        errorLines.emplace(index, d.line);
    }
    if (errorLines.empty())
        return {};
    std::vector<bool> inError(program.size(), false);
    for (std::size_t i = 0; i < program.size(); ++i) {
        const toolpath::SourceRef& source = program.source(i);
        inError[i] = errorLines.count({source.file, source.line}) > 0;
    }
    return inError;
}

}  // namespace camwb::nc
