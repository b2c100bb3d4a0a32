// The NC interpreters report base::Diagnostic (file, line, column, severity, message); these
// names keep the interpreters' code short. Interpreters collect them and carry on where they
// safely can; they never throw.
#pragma once

#include "base/Diagnostic.h"

namespace camwb::nc {

using base::Diagnostic;
using base::formatDiagnostic;
using base::hasErrors;
using base::Severity;
using base::severityName;

}  // namespace camwb::nc
