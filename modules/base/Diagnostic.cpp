#include "base/Diagnostic.h"

#include <algorithm>

namespace camwb::base {

const char* severityName(Severity severity)
{
    switch (severity) {
    case Severity::Note:
        return "note";
    case Severity::Warning:
        return "warning";
    case Severity::Error:
        return "error";
    }
    return "error";
}

std::string formatDiagnostic(const Diagnostic& d)
{
    std::string out;
    if (!d.file.empty()) {
        out = d.file;
        if (d.line > 0)
            out += ':' + std::to_string(d.line);
        if (d.line > 0 && d.column > 0)
            out += ':' + std::to_string(d.column);
        out += ": ";
    }
    out += severityName(d.severity);
    out += ": ";
    out += d.message;
    return out;
}

bool hasErrors(const std::vector<Diagnostic>& diagnostics) { return countOf(diagnostics, Severity::Error) > 0; }

std::size_t countOf(const std::vector<Diagnostic>& diagnostics, Severity severity)
{
    return static_cast<std::size_t>(std::count_if(diagnostics.begin(), diagnostics.end(),
                                                  [severity](const Diagnostic& d) { return d.severity == severity; }));
}

}  // namespace camwb::base
