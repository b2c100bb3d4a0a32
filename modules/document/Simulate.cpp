#include "document/Simulate.h"

#include "document/JobPipeline.h"
#include "document/NcTrace.h"
#include "nc/ToolTable.h"
#include "occ/Model.h"
#include "post/PostRegistry.h"
#include "toolpath/Toolpath.h"

#include <cmath>

namespace camwb::document {

sim::TriangleMesh designMesh(const occ::Model& model, double deflectionMm)
{
    const occ::DisplayMesh display = model.mesh(deflectionMm);
    sim::TriangleMesh mesh;
    mesh.positions = display.positions;
    mesh.triangles = display.triangles;
    return mesh;
}

base::Result<std::optional<kinematics::Machine>> jobMachine(const Job& job)
{
    auto post = loadJobPost(job, post::defaultPostDirs());
    if (!post)
        return post.error();
    return post::machineForPost(post.value().info(), job.machineId, kinematics::defaultMachineDirs());
}

double defaultStockResolution(const base::Box3& box)
{
    const double area = (box.max.x - box.min.x) * (box.max.y - box.min.y);
    double r = 0.1;
    while (area / (r * r) > 4e6)
        r *= 2;
    return r;
}

base::Box3 jobStockBox(const Job& job, const occ::Model& model)
{
    if (const std::optional<base::Box3> box = job.stock.box())
        return *box;
    return designMesh(model).bounds();
}

void sizeTools(toolpath::Toolpath& program, const std::map<int, toolpath::Tool>& tools)
{
    for (std::size_t i = 0; i < program.size(); ++i) {
        auto* change = std::get_if<toolpath::ToolChange>(&program.record(i));
        if (!change || change->tool.diameterMm > 0)
            continue;
        if (const auto it = tools.find(change->tool.number); it != tools.end())
            change->tool = it->second;
    }
}

std::map<int, toolpath::Tool> toolsOf(const nc::ToolTable& table)
{
    std::map<int, toolpath::Tool> tools;
    for (const auto& [number, entry] : table.tools()) {
        toolpath::Tool& tool = tools[number];
        tool.number = number;
        tool.name = entry.comment;
        tool.diameterMm = entry.diameterMm;
        tool.lengthMm = entry.lengthMm;
    }
    return tools;
}

RecordPlace placeOfRecord(const NcTrace& trace, std::int64_t record)
{
    return placeOfRecord(trace.result.files, trace.program, record);
}

RecordPlace placeOfRecord(const std::vector<std::string>& files, const toolpath::Toolpath& program, std::int64_t record)
{
    RecordPlace place;
    if (record < 0 || static_cast<std::size_t>(record) >= program.size()) {
        place.file = files.empty() ? std::string() : files.front();
        return place;
    }
    const toolpath::SourceRef& source = program.source(static_cast<std::size_t>(record));
    place.file = source.file >= 0 && source.file < static_cast<int>(files.size()) ? files[source.file]
                 : files.empty()                                                  ? std::string()
                                                                                  : files.front();
    place.line = std::max(source.line, 0);
    return place;
}

RecordPlace placeOfRecord(const Job& job, const std::string& jobPath, const toolpath::Toolpath& program,
                          std::int64_t record)
{
    RecordPlace place;
    place.file = jobPath;
    if (record < 0 || static_cast<std::size_t>(record) >= program.size())
        return place;
    const int op = program.source(static_cast<std::size_t>(record)).operationIndex;
    if (op >= 0 && op < static_cast<int>(job.operations.size()))
        place.operation = job.operations[op].name();
    return place;
}

}  // namespace camwb::document
