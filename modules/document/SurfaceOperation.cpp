#include "document/detail/SurfaceOperation.h"

#include "base/NumberFormat.h"
#include "document/OperationGeometry.h"
#include "document/Simulate.h"
#include "ops/ParallelOp.h"
#include "ops/Pocket3dOp.h"
#include "ops/WaterlineOp.h"
#include "ops/surface/Silhouette.h"
#include "sim/HeightField.h"
#include "sim/Moves.h"
#include "sim/StockRun.h"

#include <algorithm>
#include <set>

namespace camwb::document::detail {

namespace {

std::string label(const Operation& op) { return std::string(kindLabel(op.kind())) + " \"" + op.name() + "\""; }

// The model's triangles, and those of the selected faces alone, each welded across face edges.
struct SurfaceMeshes {
    sim::TriangleMesh model;
    sim::TriangleMesh selected;
};

SurfaceMeshes meshesOf(const occ::Model& model, const std::vector<int>& faces, double deflectionMm)
{
    const occ::DisplayMesh display = model.mesh(deflectionMm);
    sim::TriangleMesh all;
    all.positions = display.positions;
    all.triangles = display.triangles;
    SurfaceMeshes meshes;
    if (!faces.empty()) {
        const std::set<int> wanted(faces.begin(), faces.end());
        sim::TriangleMesh selected;
        selected.positions = display.positions;
        for (std::size_t t = 0; t < display.triangleFace.size(); ++t)
            if (wanted.contains(display.triangleFace[t]))
                selected.triangles.insert(selected.triangles.end(), display.triangles.begin() + 3 * t,
                                          display.triangles.begin() + 3 * t + 3);
        meshes.selected = sim::weldVertices(selected);
    }
    meshes.model = sim::weldVertices(all);
    return meshes;
}

// The planar faces facing +Z: exact floor heights from the B-rep.
std::vector<double> flatLevelsOf(const occ::Model& model)
{
    std::vector<double> levels;
    for (int f = 1; f <= model.faceCount(); ++f) {
        const occ::FaceInfo face = model.face(f);
        if (face.planar && face.normal.z > 1 - 1e-9)
            levels.push_back(face.planeZ);
    }
    std::sort(levels.begin(), levels.end());
    levels.erase(std::unique(levels.begin(), levels.end()), levels.end());
    return levels;
}

// How deep the tool must go by default: where the stock reaches beyond the model's sides, down to
// the model's bottom (clearing round it); else to the lowest surface of `mesh` that faces up, the
// deepest point a tool from above touches (the floor of a cavity, not the block's underside).
double lowestReach(const sim::TriangleMesh& mesh, const base::Box3& stock, const base::Vec3& modelMin,
                   const base::Vec3& modelMax)
{
    const double eps = 1e-3;
    if (stock.min.x < modelMin.x - eps || stock.min.y < modelMin.y - eps || stock.max.x > modelMax.x + eps ||
        stock.max.y > modelMax.y + eps)
        return modelMin.z;
    double lowest = modelMax.z;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const base::Vec3 a = mesh.vertex(mesh.triangles[3 * t]), b = mesh.vertex(mesh.triangles[3 * t + 1]),
                         c = mesh.vertex(mesh.triangles[3 * t + 2]);
        if ((b - a).cross(c - a).z > 1e-12)
            lowest = std::min({lowest, a.z, b.z, c.z});
    }
    return lowest;
}

// The stock after the enabled operations before `index` (three-axis ones: a tilted plane or a
// swarf cut is not a height field's to follow, so rest machining refuses to guess after one).
base::Result<std::unique_ptr<sim::HeightField>> restStockBefore(const Job& job, int index, const occ::Model& model,
                                                                const base::Box3& box, const ops::Progress& progress)
{
    auto stock = std::make_unique<sim::HeightField>(box, defaultStockResolution(box));
    for (int j = 0; j < index; ++j) {
        const Operation& before = job.operations[j];
        if (!before.enabled)
            continue;
        if (before.kind() == OperationKind::Swarf || before.plane.mode != WorkingPlaneSpec::Mode::Flat)
            return base::makeError(label(job.operations[index]) +
                                   ": rest machining follows three-axis operations only; " + label(before) +
                                   " tilts the tool");
        // Cancelling this operation cancels the ones it recomputes (no progress: theirs is not its own).
        auto cut = computeOperation(job, j, model, ops::Progress{{}, progress.cancel});
        if (!cut)
            return base::makeError(label(job.operations[index]) + ": rest machining needs what " + label(before) +
                                   " leaves, and it fails: " + cut.error().message);
        toolpath::Toolpath program;
        program.add(toolpath::ToolChange{job.tool(before.toolNumber)->tool});
        program.append(cut->toolpath);
        const sim::MoveList moves = sim::buildMoves(program);
        sim::StockRun run(moves, *stock);
        run.cutTo(moves.moves.size());
    }
    return stock;
}

}  // namespace

base::Result<ops::OpResult> computeSurfaceOperation(const Job& job, int index, const occ::Model& model,
                                                    const ops::Progress& progress,
                                                    std::optional<ops::Heights>* heightsUsed)
{
    const Operation& op = job.operations[index];
    auto fail = [&](const std::string& message) { return base::makeError(label(op) + ": " + message); };
    if (model.empty())
        return fail("no model is loaded");
    if (!model.hasBRep())
        return fail("the model has no solid geometry (STL meshes cannot be machined from)");
    if (op.plane.mode != WorkingPlaneSpec::Mode::Flat)
        return fail("3D operations cut from +Z; a working plane is not supported");
    if (!op.geometry.edges.empty() || !op.geometry.holes.empty())
        return fail("works on faces (the area to cut) or the whole model; edges and holes are not supported");
    for (int face : op.geometry.faces)
        if (face < 1 || face > model.faceCount())
            return fail("face " + std::to_string(face) + " is not in the model (it has " +
                        std::to_string(model.faceCount()) + " faces)");

    const double tolerance = toleranceOf(op);
    const SurfaceMeshes meshes = meshesOf(model, op.geometry.faces, tolerance);
    ops::Heights heights = resolveHeights(op, OperationGeometry{}, model, job.stock);
    const base::Box3 stockBox = jobStockBox(job, model);
    if (!op.heights.finalZ)
        heights.finalZ = lowestReach(op.geometry.faces.empty() ? meshes.model : meshes.selected, stockBox,
                                     model.boundsMin(), model.boundsMax());
    if (heightsUsed)
        *heightsUsed = heights;

    ops::SurfaceInput input;
    input.model = &meshes.model;
    if (!op.geometry.faces.empty()) {
        input.boundary = ops::surface::silhouette(meshes.selected, tolerance);
        if (input.boundary.empty())
            return fail("the selected faces have no area seen from above (vertical faces only)");
    }
    input.stock = stockBox;
    input.flatLevels = flatLevelsOf(model);
    std::unique_ptr<sim::HeightField> rest;

    const ops::ToolController& tc = *job.tool(op.toolNumber);
    return std::visit(
        [&](auto params) -> base::Result<ops::OpResult> {
            using P = decltype(params);
            if constexpr (requires { params.heights; })
                params.heights = heights;
            if constexpr (std::is_same_v<P, ops::Pocket3dParams>) {
                if (params.restMachining) {
                    auto before = restStockBefore(job, index, model, input.stock, progress);
                    if (!before)
                        return before.error();
                    rest = std::move(before).value();
                    input.restStock = rest.get();
                }
                return ops::computePocket3d(input, params, tc, index, progress);
            } else if constexpr (std::is_same_v<P, ops::WaterlineParams>) {
                return ops::computeWaterline(input, params, tc, index, progress);
            } else if constexpr (std::is_same_v<P, ops::ParallelParams>) {
                return ops::computeParallel(input, params, tc, index, progress);
            } else {
                return fail("is not a 3D operation");
            }
        },
        op.params);
}

}  // namespace camwb::document::detail
