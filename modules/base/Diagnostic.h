// The one diagnostic type: what is wrong or doubtful, where (file, line, column) and how bad.
// NC interpreters, the post kernel, the machine limit check, CL importers and operations all
// report through it, so the CLI and the GUI print and sort them one way.
#pragma once

#include <string>
#include <vector>

namespace camwb::base {

enum class Severity { Note, Warning, Error };

struct Diagnostic {
    Severity severity = Severity::Error;
    std::string file;  // empty when the finding is not about a file (a CL record, an operation)
    int line = 0;      // 1-based, 0 = the whole file
    int column = 0;    // 1-based, 0 = the whole line
    std::string message;
};

// "file:line:column: severity: message" as compilers write it; unknown parts are left out, and
// without a file the location is left out too ("warning: message").
std::string formatDiagnostic(const Diagnostic& diagnostic);
const char* severityName(Severity severity);

bool hasErrors(const std::vector<Diagnostic>& diagnostics);
std::size_t countOf(const std::vector<Diagnostic>& diagnostics, Severity severity);

inline Diagnostic warningDiagnostic(std::string message, std::string file = {}, int line = 0, int column = 0)
{
    return {Severity::Warning, std::move(file), line, column, std::move(message)};
}

}  // namespace camwb::base
