// Diagnostics of the NC interpreters: what is wrong (or doubtful) in a program, where, and how
// bad. Interpreters collect them and carry on where they safely can; they never throw.
#pragma once

#include <string>
#include <vector>

namespace camwb::nc {

enum class Severity { Note, Warning, Error };

struct Diagnostic {
    Severity severity = Severity::Error;
    std::string file;  // path as given to the interpreter (subprograms: their own path)
    int line = 0;      // 1-based
    int column = 0;    // 1-based, 0 = the whole line
    std::string message;
};

// "file:line:column: error: message" (column left out when 0), as compilers write it.
std::string formatDiagnostic(const Diagnostic& diagnostic);
const char* severityName(Severity severity);

bool hasErrors(const std::vector<Diagnostic>& diagnostics);

}  // namespace camwb::nc
