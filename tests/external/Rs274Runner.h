// Runs LinuxCNC's standalone interpreter on an NC file: `rs274 -t <tool table> -g <file>` with
// stdin closed, in a scratch folder (rs274 may leave files in its working directory). Qt's
// QProcess keeps stdout (the canonical trace) apart from stderr (errors, PRINT comments).
#pragma once

#include "base/Result.h"

#include <string>
#include <vector>

namespace camwb::external {

struct Rs274Run {
    int exitCode = -1;   // 0 = read to the end without error; 1 = an interpreter error (on stderr)
    std::string trace;   // stdout: one canonical call per line
    std::string errors;  // stderr: "executing", then the error text and the offending line
    double seconds = 0;  // wall time of the rs274 process
};

// A tool of the rs274 tool table. rs274 without an INI file works in inch machine units, so the
// table is written in inches and LinuxCNC converts it into program units (mm under G21).
struct Rs274Tool {
    int number = 1;
    double lengthMm = 0;
    double diameterMm = 0;
};

// Writes `tools` as a LinuxCNC tool table ("T1 P1 Z... D... ;") at `path`.
base::Status writeRs274ToolTable(const std::string& path, const std::vector<Rs274Tool>& tools);

// `rs274Binary` is the path CMake found; fails only when the process cannot run or hangs. rs274
// runs with HOME = workDir (its tool table lives in $HOME/.tool.mmap); exitCode -1: it crashed.
base::Result<Rs274Run> runRs274(const std::string& rs274Binary, const std::string& ngcFile,
                                const std::string& toolTable, const std::string& workDir, int timeoutMs = 120000);

}  // namespace camwb::external
