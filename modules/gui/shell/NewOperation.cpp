#include "gui/shell/NewOperation.h"

#include "base/NumberFormat.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace camwb::gui {

namespace {

using document::OperationKind;

constexpr double kLevelEpsMm = 1e-6;
constexpr double kSameDiameterMm = 0.1;

// A diameter in a name or message ("D6.35"), the same in every locale: names are saved in the job.
std::string formatMm(double value) { return base::formatGeneral(value, 6); }

bool isUpFacing(const occ::FaceInfo& face) { return face.planar && face.normal.z > 1.0 - 1e-9; }
bool isDrill(const ops::ToolController& tc) { return tc.tool.kind == "drill"; }
bool isGroovingTool(const ops::ToolController& tc) { return tc.tool.kind == "groove"; }

int nextToolNumber(const document::Job& job)
{
    int number = 0;
    for (const ops::ToolController& tc : job.tools)
        number = std::max(number, tc.tool.number);
    return number + 1;
}

ops::ToolController defaultEndMill(int number)
{
    ops::ToolController tc;
    tc.tool = {number, "Flat end mill D10", "flat", 10.0, 0.0, 22.0, 50.0, 3};
    tc.spindleRpm = 3000;
    tc.cuttingFeedMmPerMin = 600;
    tc.plungeFeedMmPerMin = 150;
    return tc;
}

// Sized for the smallest hole of the model, so that it fits every hole.
ops::ToolController defaultDrill(int number, double diameterMm)
{
    ops::ToolController tc;
    tc.tool = {number, "Twist drill D" + formatMm(diameterMm), "drill", diameterMm, 0.0, 40.0, 80.0, 2};
    tc.tool.pointAngleDeg = 118;
    tc.spindleRpm = 1500;
    tc.cuttingFeedMmPerMin = 120;
    tc.plungeFeedMmPerMin = 120;
    return tc;
}

// The thesis' grooving insert (seed-001: 3 mm wide, reference point its left corner) with the
// Kod 5 frame's data; a lathe's tool controller carries no mm/min feeds (the groove gives mm/rev).
ops::ToolController defaultGroovingTool(int number)
{
    ops::ToolController tc;
    tc.tool = {number, "Grooving insert W3", "groove", 3.0, 0.0, 25.0, 100.0, 1};
    tc.spindleRpm = 3000;
    return tc;
}

std::string defaultName(OperationKind kind, const document::Job& job)
{
    static const char* const names[] = {"Contour",   "Pocket",    "Helix",    "Drilling", "Swarf",
                                        "3D Pocket", "Waterline", "Parallel", "Groove"};
    const std::string base = names[static_cast<int>(kind)];
    int count = 1;
    for (const document::Operation& op : job.operations)
        count += op.kind() == kind ? 1 : 0;
    return base + " " + std::to_string(count);
}

document::OperationParams defaultParams(OperationKind kind)
{
    switch (kind) {
    case OperationKind::Contour:
        return ops::ContourParams{};
    case OperationKind::Pocket:
        return ops::PocketParams{};
    case OperationKind::Helix:
        return ops::HelixParams{};
    case OperationKind::Swarf:
        return ops::SwarfParams{};
    case OperationKind::Pocket3d:
        return ops::Pocket3dParams{};
    case OperationKind::Waterline:
        return ops::WaterlineParams{};
    case OperationKind::Parallel:
        return ops::ParallelParams{};
    case OperationKind::Groove:
        return ops::GrooveParams{};
    case OperationKind::Drill:
        break;
    }
    return ops::DrillParams{};
}

// The first selected face swarf milling can follow; else the model's first curved ruled face (a
// cone or cylinder that is no hole); 0 if none.
int swarfFace(const occ::Model& model, const std::vector<int>& selected)
{
    for (int f : selected)
        if (model.swarfFace(f).ok())
            return f;
    const std::vector<geom::Hole> holes = model.holes();
    for (int f = 1; f <= model.faceCount(); ++f) {
        auto face = model.swarfFace(f);
        const bool hole =
            std::any_of(holes.begin(), holes.end(), [f](const geom::Hole& h) { return h.faceIndex == f; });
        if (face.ok() && face->surface != "plane" && !hole && !model.cylinderAxis(f))
            return f;
    }
    return 0;
}

std::vector<int> selectedPlanarFaces(const occ::Model& model, const std::vector<int>& selected)
{
    std::vector<int> faces;
    for (int f : selected)
        if (model.face(f).planar && std::abs(model.face(f).normal.z) > 1.0 - 1e-9)
            faces.push_back(f);
    return faces;
}

std::vector<int> selectedHoles(const std::vector<geom::Hole>& holes, const std::vector<int>& selected)
{
    std::vector<int> faces;
    for (int f : selected)
        if (std::any_of(holes.begin(), holes.end(), [f](const geom::Hole& h) { return h.faceIndex == f; }))
            faces.push_back(f);
    return faces;
}

base::Result<std::vector<int>> pocketFloor(const occ::Model& model)
{
    const int top = model.topPlanarFace();
    const double topZ = top > 0 ? model.face(top).planeZ : model.boundsMax().z;
    int best = 0;
    bool bestHasIslands = false;
    double bestArea = 0;
    for (int f = 1; f <= model.faceCount(); ++f) {
        const occ::FaceInfo face = model.face(f);
        if (!isUpFacing(face) || face.planeZ > topZ - kLevelEpsMm)
            continue;
        auto region = model.planarFaceRegion(f);
        const bool hasIslands = region && !region->holes.empty();
        if (best == 0 || hasIslands > bestHasIslands || (hasIslands == bestHasIslands && face.areaMm2 > bestArea)) {
            best = f;
            bestHasIslands = hasIslands;
            bestArea = face.areaMm2;
        }
    }
    if (best == 0)
        return base::Error{"pocket: the model has no upward planar face below its top (a pocket floor); "
                           "select the floor face"};
    return std::vector<int>{best};
}

base::Result<std::vector<int>> helixHoles(const std::vector<geom::Hole>& holes, double toolDiameterMm)
{
    double largest = 0;
    for (const geom::Hole& h : holes)
        if (h.diameterMm > toolDiameterMm)
            largest = std::max(largest, h.diameterMm);
    if (largest == 0)
        return base::Error{"helix: no hole of the model is larger than the tool (Ø" + formatMm(toolDiameterMm) +
                           " mm)"};
    std::vector<int> faces;
    for (const geom::Hole& h : holes)
        if (std::abs(h.diameterMm - largest) < 0.01)
            faces.push_back(h.faceIndex);
    return faces;
}

std::vector<int> drillHoles(const std::vector<geom::Hole>& holes, double drillDiameterMm)
{
    double nearest = holes.front().diameterMm;
    for (const geom::Hole& h : holes)
        if (std::abs(h.diameterMm - drillDiameterMm) < std::abs(nearest - drillDiameterMm))
            nearest = h.diameterMm;
    const double wanted = std::abs(nearest - drillDiameterMm) <= kSameDiameterMm ? drillDiameterMm : nearest;
    std::vector<int> faces;
    for (const geom::Hole& h : holes)
        if (std::abs(h.diameterMm - wanted) <= kSameDiameterMm)
            faces.push_back(h.faceIndex);
    return faces;
}

// The end mill for hole milling: the largest one smaller than the largest hole (or, with holes
// selected, than the smallest of them), so it fits with a real helix; nullptr when none fits.
const ops::ToolController* helixTool(const document::Job& job, const std::vector<geom::Hole>& holes,
                                     const std::vector<int>& selected)
{
    double limit = selected.empty() ? 0.0 : 1e300;
    for (const geom::Hole& h : holes) {
        const bool isSelected = std::find(selected.begin(), selected.end(), h.faceIndex) != selected.end();
        if (selected.empty())
            limit = std::max(limit, h.diameterMm);
        else if (isSelected)
            limit = std::min(limit, h.diameterMm);
    }
    const ops::ToolController* best = nullptr;
    for (const ops::ToolController& tc : job.tools)
        if (!isDrill(tc) && tc.tool.diameterMm < limit && (!best || tc.tool.diameterMm > best->tool.diameterMm))
            best = &tc;
    return best;
}

}  // namespace

const ops::ToolController* suitedTool(OperationKind kind, const document::Job& job)
{
    const bool wantDrill = kind == OperationKind::Drill, wantGroove = kind == OperationKind::Groove;
    // Finishing a surface wants a ball-nose where the job has one.
    if (kind == OperationKind::Waterline || kind == OperationKind::Parallel)
        for (const ops::ToolController& tc : job.tools)
            if (tc.tool.kind == "ball")
                return &tc;
    for (const ops::ToolController& tc : job.tools)
        if (isDrill(tc) == wantDrill && isGroovingTool(tc) == wantGroove)
            return &tc;
    return nullptr;
}

base::Result<OperationProposal> proposeOperation(OperationKind kind, const document::Job& job, const occ::Model& model,
                                                 const std::vector<int>& selectedFaces)
{
    const std::string what = document::kindLabel(kind);
    OperationProposal proposal;
    document::Operation& op = proposal.operation;
    op.params = defaultParams(kind);
    op.setName(defaultName(kind, job));
    if (kind == OperationKind::Groove) {  // the groove is given by its numbers: no model needed
        const ops::ToolController* tool = suitedTool(kind, job);
        if (tool == nullptr)
            proposal.newTool = defaultGroovingTool(nextToolNumber(job));
        op.toolNumber = tool != nullptr ? tool->tool.number : proposal.newTool->tool.number;
        return proposal;
    }
    if (!model.hasBRep())
        return base::Error{what + ": needs a solid model (STEP, IGES or BREP); import one first"};

    const std::vector<geom::Hole> holes =
        kind == OperationKind::Helix || kind == OperationKind::Drill ? model.holes() : std::vector<geom::Hole>{};
    if ((kind == OperationKind::Helix || kind == OperationKind::Drill) && holes.empty())
        return base::Error{what + ": the model has no vertical cylindrical holes"};

    const ops::ToolController* tool =
        kind == OperationKind::Helix ? helixTool(job, holes, selectedHoles(holes, selectedFaces)) : nullptr;
    if (tool == nullptr)
        tool = suitedTool(kind, job);
    if (tool == nullptr) {
        if (kind == OperationKind::Drill) {
            double smallest = holes.front().diameterMm;
            for (const geom::Hole& h : holes)
                smallest = std::min(smallest, h.diameterMm);
            proposal.newTool = defaultDrill(nextToolNumber(job), smallest);
        } else {
            proposal.newTool = defaultEndMill(nextToolNumber(job));
        }
        tool = &*proposal.newTool;
    }
    op.toolNumber = tool->tool.number;

    switch (kind) {
    case OperationKind::Contour:
        op.geometry.faces = selectedPlanarFaces(model, selectedFaces);
        if (op.geometry.faces.empty() && model.topPlanarFace() > 0)
            op.geometry.faces = {model.topPlanarFace()};
        if (op.geometry.faces.empty())
            return base::Error{what + ": the model has no upward planar face; select faces or edges"};
        break;
    case OperationKind::Pocket: {
        op.geometry.faces = selectedPlanarFaces(model, selectedFaces);
        if (op.geometry.faces.empty()) {
            auto floor = pocketFloor(model);
            if (!floor)
                return floor.error();
            op.geometry.faces = floor.value();
        }
        break;
    }
    case OperationKind::Helix: {
        op.geometry.holes = selectedHoles(holes, selectedFaces);
        if (op.geometry.holes.empty()) {
            auto chosen = helixHoles(holes, tool->tool.diameterMm);
            if (!chosen)
                return chosen.error();
            op.geometry.holes = chosen.value();
        }
        break;
    }
    case OperationKind::Drill:
        op.geometry.holes = selectedHoles(holes, selectedFaces);
        if (op.geometry.holes.empty())
            op.geometry.holes = drillHoles(holes, tool->tool.diameterMm);
        break;
    case OperationKind::Swarf:
        op.geometry.faces = {swarfFace(model, selectedFaces)};
        if (op.geometry.faces.front() == 0)
            return base::Error{what + ": the model has no ruled face (cone, cylinder) to follow; select a face"};
        break;
    case OperationKind::Pocket3d:
    case OperationKind::Waterline:
    case OperationKind::Parallel:
        op.geometry.faces = selectedFaces;  // the area they bound; none: the whole model
        break;
    case OperationKind::Groove:
        break;  // returned above
    }
    return proposal;
}

}  // namespace camwb::gui
