#include "document/detail/SwarfOperation.h"

#include "base/NumberFormat.h"
#include "document/OperationGeometry.h"

namespace camwb::document::detail {

namespace {

std::string fmt(double v) { return base::NumberFormat{3, true}.format(v); }
std::string point(const base::Vec3& p) { return "(" + fmt(p.x) + ", " + fmt(p.y) + ", " + fmt(p.z) + ")"; }

// The poses of the computed records, and for each the record it came from.
std::vector<occ::ToolPose> posesOf(const toolpath::Toolpath& path, std::vector<std::size_t>& records)
{
    std::vector<occ::ToolPose> poses;
    for (std::size_t i = 0; i < path.size(); ++i)
        if (const auto* move = std::get_if<toolpath::ToolAxisMove>(&path.record(i))) {
            poses.push_back({move->tip, move->axis});
            records.push_back(i);
        }
    return poses;
}

}  // namespace

base::Result<ops::OpResult> computeSwarfOperation(const Job& job, int index, const occ::Model& model,
                                                  const ops::Progress& progress,
                                                  std::optional<ops::Heights>* heightsUsed)
{
    const Operation& op = job.operations[index];
    const std::string what = "swarf \"" + op.name() + "\"";
    auto fail = [&](const std::string& message) { return base::makeError(what + ": " + message); };
    if (op.plane.mode != WorkingPlaneSpec::Mode::Flat)
        return fail("a simultaneous five-axis operation takes no working plane (its tool axis follows the face)");
    auto geometry = resolveGeometry(op, model);
    if (!geometry)
        return geometry.error();
    auto face = model.swarfFace(op.geometry.faces.front(), op.geometry.edges.empty() ? 0 : op.geometry.edges.front());
    if (!face)
        return fail(face.error().message);
    ops::SwarfParams params = std::get<ops::SwarfParams>(op.params);
    params.heights = resolveHeights(op, geometry.value(), model, job.stock);
    if (heightsUsed)
        *heightsUsed = params.heights;
    const ops::ToolController& tc = *job.tool(op.toolNumber);
    const ops::SwarfDrive drive{face->t0, face->t1, face->closed, face->at};
    auto result = ops::computeSwarf(drive, params, tc, index, progress);
    if (!result)
        return result;
    // The gouge check: the flutes (or, where the tool states none, three diameters) and the bottom.
    std::vector<std::size_t> records;
    const std::vector<occ::ToolPose> poses = posesOf(result->toolpath, records);
    const double length = tc.tool.fluteLengthMm > 0 ? tc.tool.fluteLengthMm : 3 * tc.tool.diameterMm;
    const std::optional<occ::Gouge> gouge =
        model.firstGouge(poses, tc.tool.diameterMm / 2, length, params.gougeToleranceMm);
    if (gouge) {
        const std::string where = gouge->face > 0 ? "face " + std::to_string(gouge->face) : "the model";
        return fail("the tool gouges " + where + " by more than " + fmt(params.gougeToleranceMm) + " mm at " +
                    point(gouge->point) + ", on the move to " + point(poses[gouge->pose].tip) + " (CL record " +
                    std::to_string(records[gouge->pose] + 1) + ")");
    }
    return result;
}

}  // namespace camwb::document::detail
