#include "document/OperationGeometry.h"

#include "document/detail/OperationPlanes.h"
#include "document/detail/SurfaceOperation.h"
#include "document/detail/SwarfOperation.h"

#include <algorithm>
#include <cmath>

namespace camwb::document {

namespace {

std::string label(const Operation& op) { return std::string(kindLabel(op.kind())) + " \"" + op.name() + "\""; }

base::Error refError(const Operation& op, const std::string& message)
{
    return base::makeError(label(op) + ": " + message);
}

// Pocket faces: the largest faces are boundaries; a face lying inside another one's outer loop
// (and not in one of its holes) is an island of it: its outer loop becomes a hole there.
std::vector<geom::Region> nestFaces(std::vector<geom::Region> faces)
{
    std::stable_sort(faces.begin(), faces.end(),
                     [](const geom::Region& a, const geom::Region& b) { return a.area() > b.area(); });
    std::vector<geom::Region> boundaries;
    for (geom::Region& face : faces) {
        // A point just inside the face (left of its ccw outer loop), so that a face whose outline
        // coincides with another face's hole (an island's top over its floor) is not nested there.
        const geom::Segment& first = face.outer.segments.front();
        const base::Vec2 probe = first.pointAt(0.5) + first.startTangent().leftNormal() * 1e-3;
        auto host = std::find_if(boundaries.begin(), boundaries.end(),
                                 [&](const geom::Region& b) { return b.contains(probe); });
        if (host == boundaries.end())
            boundaries.push_back(std::move(face));
        else
            host->holes.push_back(face.outer.reversed());
    }
    return boundaries;
}

base::Result<OperationGeometry> resolveFaces(const Operation& op, const occ::Model& model, double tolerance,
                                             OperationGeometry geometry)
{
    std::vector<geom::Region> faces;
    for (int face : op.geometry.faces) {
        if (face < 1 || face > model.faceCount())
            return refError(op, "face " + std::to_string(face) + " is not in the model (it has " +
                                    std::to_string(model.faceCount()) + " faces)");
        if (op.kind() == OperationKind::Contour) {
            auto outline = model.planarFaceOuterProfile(face, tolerance);
            if (!outline)
                return refError(op, outline.error().message);
            geometry.contours.push_back(std::move(outline).value());
        } else {
            auto region = model.planarFaceRegion(face, tolerance);
            if (!region)
                return refError(op, region.error().message);
            faces.push_back(std::move(region).value());
        }
    }
    if (!faces.empty())
        geometry.regions = nestFaces(std::move(faces));
    return geometry;
}

}  // namespace

double toleranceOf(const Operation& op)
{
    return std::visit(
        [](const auto& p) {
            if constexpr (requires { p.toleranceMm; })
                return p.toleranceMm;
            else
                return 0.01;
        },
        op.params);
}

base::Result<OperationGeometry> resolveGeometry(const Operation& op, const occ::Model& model)
{
    const OperationKind kind = op.kind();
    const bool wantsHoles = kind == OperationKind::Helix || kind == OperationKind::Drill;
    if (model.empty())
        return refError(op, "no model is loaded");
    if (!model.hasBRep())
        return refError(op, "the model has no solid geometry (STL meshes cannot be machined from)");
    if (wantsHoles && !op.geometry.faces.empty())
        return refError(op, kind == OperationKind::Helix ? "works on holes; select holes or circular edges, not faces"
                                                         : "works on holes; select holes, not faces or edges");
    if (kind == OperationKind::Drill && !op.geometry.edges.empty())
        return refError(op, "works on holes; select holes, not faces or edges");
    if (!wantsHoles && !op.geometry.holes.empty())
        return refError(op, "works on faces and edges, not holes");
    if (kind == OperationKind::Pocket && !op.geometry.edges.empty())
        return refError(op, "a pocket is made from faces; edges are not supported");
    if (kind == OperationKind::Swarf) {
        // The face and its drive edge are resolved by the model's swarfFace.
        if (op.geometry.faces.size() != 1)
            return refError(op, "follows one ruled face: select exactly one face (" +
                                    std::to_string(op.geometry.faces.size()) + " selected)");
        if (op.geometry.edges.size() > 1)
            return refError(op, "drives along one edge of its face, or its lowest edge when none is selected");
        return OperationGeometry{};
    }
    if (isSurfaceKind(kind)) {
        // The model's surface is the geometry; selected faces (any shape) bound the area.
        if (!op.geometry.edges.empty())
            return refError(op, "works on faces (the area to cut) or the whole model; edges are not supported");
        for (int face : op.geometry.faces)
            if (face < 1 || face > model.faceCount())
                return refError(op, "face " + std::to_string(face) + " is not in the model (it has " +
                                        std::to_string(model.faceCount()) + " faces)");
        return OperationGeometry{};
    }

    const double tolerance = toleranceOf(op);
    OperationGeometry geometry;
    if (kind == OperationKind::Helix && !op.geometry.edges.empty()) {
        // A picked circle has a position and a diameter but no depth: the heights give it.
        if (std::get<ops::HelixParams>(op.params).depthsFromHoles)
            return refError(op, "a picked circle (edge " + std::to_string(op.geometry.edges.front()) +
                                    ") has no depth: untick \"depths from holes\" and set the final depth");
        for (int edge : op.geometry.edges) {
            auto circle = model.circleEdgeAsHole(edge);
            if (!circle)
                return refError(op, circle.error().message);
            geometry.holes.push_back(circle.value());
        }
    } else if (!op.geometry.edges.empty()) {
        auto chains = model.edgeChains(op.geometry.edges, tolerance);
        if (!chains)
            return refError(op, chains.error().message);
        geometry.contours = std::move(chains).value();
    }
    if (!op.geometry.holes.empty()) {
        const std::vector<geom::Hole> all = model.holes();
        for (int face : op.geometry.holes) {
            auto hole = std::find_if(all.begin(), all.end(), [&](const geom::Hole& h) { return h.faceIndex == face; });
            if (hole == all.end())
                return refError(op, "face " + std::to_string(face) + " is not a vertical cylindrical hole");
            geometry.holes.push_back(*hole);
        }
    }
    auto resolved = resolveFaces(op, model, tolerance, std::move(geometry));
    if (!resolved)
        return resolved;
    if (resolved->contours.empty() && resolved->regions.empty() && resolved->holes.empty())
        return refError(op,
                        "nothing selected: choose " + std::string(wantsHoles                      ? "holes"
                                                                  : kind == OperationKind::Pocket ? "faces"
                                                                                                  : "faces or edges"));
    return resolved;
}

ops::Heights resolveHeights(const Operation& op, const OperationGeometry& geometry, const occ::Model& model,
                            const Stock& stock)
{
    const double top = std::max(stock.max.z, model.boundsMax().z);
    ops::Heights h;
    h.clearanceZ = top + 10;
    h.safeZ = top + 2;
    h.startZ = top;
    h.finalZ = model.boundsMin().z;

    double featureTop = -1e300, featureBottom = 1e300;
    for (const geom::Hole& hole : geometry.holes) {
        featureTop = std::max(featureTop, hole.topZ);
        featureBottom = std::min(featureBottom, hole.bottomZ);
    }
    switch (op.kind()) {
    case OperationKind::Pocket:
        // The floor: the lowest selected face.
        for (int face : op.geometry.faces)
            featureBottom = std::min(featureBottom, model.face(face).planeZ);
        h.finalZ = featureBottom < 1e299 ? featureBottom : h.finalZ;
        break;
    case OperationKind::Contour:
        // Through the part along a face's outline; at the level of selected edges.
        for (int edge : op.geometry.edges)
            featureBottom = std::min(featureBottom, model.edge(edge).start.z);
        if (op.geometry.faces.empty() && featureBottom < 1e299)
            h.finalZ = featureBottom;
        break;
    case OperationKind::Swarf:
        break;  // reached along the tool axis; start and final unused
    case OperationKind::Pocket3d:
    case OperationKind::Waterline:
    case OperationKind::Parallel:
        break;  // from the stock top down to the model's (or the selected faces') bottom
    case OperationKind::Groove:
        break;  // a lathe operation: its retracts are its own parameters (safety, final retract)
    case OperationKind::Helix:
    case OperationKind::Drill:
        if (featureTop > -1e299) {
            h.startZ = featureTop;
            // Picked circles have no depth of their own: down to the model's bottom by default.
            h.finalZ = op.geometry.edges.empty() ? featureBottom : model.boundsMin().z;
        }
        break;
    }
    if (op.heights.clearanceZ)
        h.clearanceZ = *op.heights.clearanceZ;
    if (op.heights.safeZ)
        h.safeZ = *op.heights.safeZ;
    if (op.heights.startZ)
        h.startZ = *op.heights.startZ;
    if (op.heights.finalZ)
        h.finalZ = *op.heights.finalZ;
    return h;
}

namespace {
base::Result<ops::OpResult> computeInPlane(const Job& job, int index, const Operation& op, const occ::Model& model,
                                           const Stock& stock, const ops::Progress& progress,
                                           std::optional<ops::Heights>* heightsUsed);
}  // namespace

base::Result<ops::OpResult> computeOperation(const Job& job, int index, const occ::Model& model,
                                             const ops::Progress& progress, std::optional<ops::Heights>* heightsUsed)
{
    if (index < 0 || index >= static_cast<int>(job.operations.size()))
        return base::makeError("no operation " + std::to_string(index + 1) + " in the job");
    const Operation& op = job.operations[index];
    if (!job.tool(op.toolNumber))
        return refError(op, "no tool number " + std::to_string(op.toolNumber) + " in the job");
    // A groove is all parameters: no model, no references, no heights.
    if (const auto* groove = std::get_if<ops::GrooveParams>(&op.params))
        return ops::computeGroove(*groove, *job.tool(op.toolNumber), index, progress);
    if (model.empty())
        return refError(op, "needs a model and the job has none (only a lathe job's groove operations need none)");
    if (op.kind() == OperationKind::Swarf)
        return detail::computeSwarfOperation(job, index, model, progress, heightsUsed);
    if (isSurfaceKind(op.kind()))
        return detail::computeSurfaceOperation(job, index, model, progress, heightsUsed);
    auto groups = detail::operationPlanes(op, model);
    if (!groups)
        return groups.error();
    if (groups->size() == 1 && !groups->front().plane.tilted())
        return computeInPlane(job, index, op, model, job.stock, progress, heightsUsed);
    // 3+2: each plane's computation on the model turned into its frame, then one section.
    std::vector<ops::OpResult> parts;
    for (const detail::PlaneGroup& group : groups.value()) {
        const toolpath::WorkingPlane& p = group.plane;
        auto framed = p.tilted() ? model.inFrame(p.origin, p.xAxis, p.zAxis) : base::Result<occ::Model>(model);
        if (!framed)
            return refError(op, framed.error().message);
        Operation inPlane = op;
        inPlane.geometry.holes = group.holes;
        auto part = computeInPlane(job, index, inPlane, framed.value(), detail::stockInFrame(job.stock, p), progress,
                                   parts.empty() ? heightsUsed : nullptr);
        if (!part)
            return part;
        parts.push_back(std::move(part).value());
    }
    return detail::joinPlanes(std::move(parts), groups.value(), index);
}

namespace {

base::Result<ops::OpResult> computeInPlane(const Job& job, int index, const Operation& op, const occ::Model& model,
                                           const Stock& stock, const ops::Progress& progress,
                                           std::optional<ops::Heights>* heightsUsed)
{
    const ops::ToolController* tc = job.tool(op.toolNumber);
    auto geometry = resolveGeometry(op, model);
    if (!geometry)
        return geometry.error();
    const ops::Heights heights = resolveHeights(op, geometry.value(), model, stock);
    if (heightsUsed)
        *heightsUsed = heights;
    const OperationGeometry& g = geometry.value();

    return std::visit(
        [&](auto params) -> base::Result<ops::OpResult> {
            using P = decltype(params);
            if constexpr (requires { params.heights; })
                params.heights = heights;
            if constexpr (std::is_same_v<P, ops::ContourParams>)
                return ops::computeContour(g.contours, params, *tc, index, progress);
            else if constexpr (std::is_same_v<P, ops::PocketParams>)
                return ops::computePocket(g.regions, params, *tc, index, progress);
            else if constexpr (std::is_same_v<P, ops::HelixParams>)
                return ops::computeHelix(g.holes, params, *tc, index, progress);
            else if constexpr (std::is_same_v<P, ops::DrillParams>)
                return ops::computeDrill(g.holes, params, *tc, index, progress);
            else
                return base::makeError(label(op) + " is computed by its own path (swarf, 3D, groove)");
        },
        op.params);
}

}  // namespace

}  // namespace camwb::document
