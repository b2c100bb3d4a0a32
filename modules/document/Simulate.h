// What simulating a job or an NC program needs from the document layer, shared by `camwb-cli
// sim` and the simulator dock: the design model as a mesh, the job's machine and stock, the
// sizes of an NC program's tools, and where a record came from.
#pragma once

#include "base/Diagnostic.h"
#include "base/Result.h"
#include "document/Job.h"
#include "kinematics/Machine.h"
#include "sim/TriangleMesh.h"
#include "toolpath/ClRecords.h"

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace camwb::nc {
class ToolTable;
}
namespace camwb::occ {
class Model;
}
namespace camwb::toolpath {
class Toolpath;
}

namespace camwb::document {

struct NcTrace;

// The model's surface within `deflectionMm` (occ's meshing), as the simulator compares with it.
sim::TriangleMesh designMesh(const occ::Model& model, double deflectionMm = 0.01);

// The machine a job runs on: the job's own, else its post's default; none when neither names one.
base::Result<std::optional<kinematics::Machine>> jobMachine(const Job& job);

// A stock resolution that keeps the stock near a million columns, for a simulation whose user
// gives none (camwb-cli sim, the setup sheet).
double defaultStockResolution(const base::Box3& box);

// The job's stock box; a job without one (min == max) takes the model's bounds.
base::Box3 jobStockBox(const Job& job, const occ::Model& model);

// NC programs name their tools but rarely size them: the tool changes of `program` without a
// diameter take the tool of that number from `tools` (the job's tools for its posted program,
// or a tool table's).
void sizeTools(toolpath::Toolpath& program, const std::map<int, toolpath::Tool>& tools);
// A tool table's tools: flat end mills of its diameters, sticking out its lengths (the table
// says no more).
std::map<int, toolpath::Tool> toolsOf(const nc::ToolTable& table);

// Where a record of a program came from, for a check's file:line: the NC file and line of a
// traced program, or the job file and the operation (by name) of a job's CL.
struct RecordPlace {
    std::string file;
    int line = 0;
    std::string operation;  // a job's operation; empty for NC
};
RecordPlace placeOfRecord(const NcTrace& trace, std::int64_t record);
// The same for a traced program kept apart from its trace: the files the trace read (result.files).
RecordPlace placeOfRecord(const std::vector<std::string>& files, const toolpath::Toolpath& program,
                          std::int64_t record);
RecordPlace placeOfRecord(const Job& job, const std::string& jobPath, const toolpath::Toolpath& program,
                          std::int64_t record);

}  // namespace camwb::document
