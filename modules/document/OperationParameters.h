// One operation parameter set by name for a single run (`camwb-cli run <job> --set Op.param=value`):
// the operation by its name or number, the parameter by its key in the job file (or the
// groove's R name), the value read as the job file would read it.
#pragma once

#include "base/Result.h"
#include "document/Job.h"

#include <string>
#include <vector>

namespace camwb::document {

// The operation named `nameOrNumber` (its name, else its 1-based number in the job) as an index.
// Errors list the job's operations.
base::Result<int> findOperation(const Job& job, const std::string& nameOrNumber);

// What `parameter` may be for `op`: the keys of its "params" in the job file, then the aliases
// (a groove's R0..R8, R10, R11, R30, and R9: the insert width, its tool's diameter).
std::vector<std::string> parameterNames(const Operation& op);

// Sets the parameter of operation `index` to `value`: a number, true/false, or an enum's name as
// the file writes it. A groove's R9 sets the diameter (insert width) of the operation's tool, so
// every operation with that tool sees it. Errors: an unknown parameter (with the valid names), a
// value of the wrong type. Ranges are the operation's own to check when it is computed.
base::Status setOperationParameter(Job& job, int index, const std::string& parameter, const std::string& value);

}  // namespace camwb::document
