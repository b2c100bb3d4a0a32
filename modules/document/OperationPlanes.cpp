#include "document/detail/OperationPlanes.h"

#include "toolpath/PlaneFrames.h"

#include <algorithm>
#include <cmath>

namespace camwb::document::detail {

namespace {

base::Error planeError(const Operation& op, const std::string& message)
{
    return base::makeError(std::string(kindLabel(op.kind())) + " \"" + op.name() + "\": " + message);
}

// The holes the model has along each direction asked about, found once per direction (turning
// the model and finding its holes is the slow part).
class HolesAlong {
public:
    explicit HolesAlong(const occ::Model& model) : m_model(model) {}

    bool has(const base::Vec3& direction, int face)
    {
        std::size_t i = 0;
        while (i < m_directions.size() && distance(m_directions[i], direction) > 1e-9)
            ++i;
        if (i == m_directions.size()) {
            m_directions.push_back(direction);
            m_holes.push_back(find(direction));
        }
        const std::vector<geom::Hole>& holes = m_holes[i];
        return std::any_of(holes.begin(), holes.end(), [&](const geom::Hole& h) { return h.faceIndex == face; });
    }

private:
    std::vector<geom::Hole> find(const base::Vec3& direction) const
    {
        if (std::abs(direction.z - 1) < 1e-9)
            return m_model.holes();
        const toolpath::WorkingPlane plane = toolpath::planeAlong(direction);
        auto framed = m_model.inFrame(plane.origin, plane.xAxis, plane.zAxis);
        return framed ? framed->holes() : std::vector<geom::Hole>{};
    }

    const occ::Model& m_model;
    std::vector<base::Vec3> m_directions;
    std::vector<std::vector<geom::Hole>> m_holes;
};

// The direction a hole is drilled from: its axis, pointing out of the opening (the sense in
// which the hole is reachable); nullopt when neither sense reaches it.
std::optional<base::Vec3> holeDirection(const occ::Model& model, HolesAlong& holes, int face)
{
    std::optional<base::Vec3> axis = model.cylinderAxis(face);
    if (!axis)
        return std::nullopt;
    if (std::abs(std::abs(axis->z) - 1) < 1e-9)
        axis = base::Vec3{0, 0, axis->z > 0 ? 1.0 : -1.0};  // exactly vertical: the flat model's holes
    for (const base::Vec3& d : {*axis, *axis * -1.0}) {
        if (holes.has(d, face))
            return d;
    }
    return std::nullopt;
}

std::vector<PlaneGroup> holeGroups(const std::vector<int>& holes, const std::vector<base::Vec3>& directions)
{
    std::vector<PlaneGroup> groups;
    std::vector<base::Vec3> groupDirection;
    for (std::size_t i = 0; i < holes.size(); ++i) {
        std::size_t g = 0;
        while (g < groups.size() && distance(groupDirection[g], directions[i]) > 1e-6)
            ++g;
        if (g == groups.size()) {
            groups.push_back({toolpath::planeAlong(directions[i]), {}});
            groupDirection.push_back(directions[i]);
        }
        groups[g].holes.push_back(holes[i]);
    }
    return groups;
}

}  // namespace

base::Result<std::vector<PlaneGroup>> operationPlanes(const Operation& op, const occ::Model& model)
{
    switch (op.plane.mode) {
    case WorkingPlaneSpec::Mode::Face: {
        const occ::FaceInfo face = model.face(op.plane.face);
        if (face.index == 0)
            return planeError(op, "working plane: no face " + std::to_string(op.plane.face) + " in the model");
        if (!face.planar)
            return planeError(op, "working plane: face " + std::to_string(op.plane.face) + " is not planar");
        return std::vector<PlaneGroup>{{toolpath::planeAlong(face.normal), op.geometry.holes}};
    }
    case WorkingPlaneSpec::Mode::Angles:
        return std::vector<PlaneGroup>{
            {toolpath::planeFromSpatialAngles(op.plane.aDeg, op.plane.bDeg, op.plane.cDeg), op.geometry.holes}};
    case WorkingPlaneSpec::Mode::Flat:
        break;
    }
    if (op.kind() != OperationKind::Drill || op.geometry.holes.empty() || !model.hasBRep())
        return std::vector<PlaneGroup>{{toolpath::WorkingPlane{}, op.geometry.holes}};
    std::vector<base::Vec3> directions;
    HolesAlong holes(model);
    for (int face : op.geometry.holes) {
        const std::optional<base::Vec3> d = holeDirection(model, holes, face);
        if (!d)
            return planeError(op, "face " + std::to_string(face) + " is not a cylindrical hole open along its axis");
        directions.push_back(*d);
    }
    return holeGroups(op.geometry.holes, directions);
}

Stock stockInFrame(const Stock& stock, const toolpath::WorkingPlane& plane)
{
    base::Box3 box;
    for (const base::Vec3& corner : base::boxCorners(stock.min, stock.max))
        box.add(plane.toLocal(corner));
    Stock framed;  // the box the tilted stock fills in the plane's frame
    framed.min = box.min;
    framed.max = box.max;
    return framed;
}

ops::OpResult joinPlanes(std::vector<ops::OpResult> parts, const std::vector<PlaneGroup>& groups, int operationIndex)
{
    ops::OpResult out;
    toolpath::WorkingPlane current;  // the plane the records added last are in
    int index = 0;
    auto add = [&](const toolpath::Record& record) { out.toolpath.add(record, {operationIndex, index++}); };
    for (std::size_t g = 0; g < parts.size(); ++g) {
        const toolpath::Toolpath& path = parts[g].toolpath;
        bool planeSet = false;
        for (std::size_t i = 0; i < path.size(); ++i) {
            const toolpath::Record& record = path.record(i);
            if (std::holds_alternative<toolpath::SectionEnd>(record))
                continue;  // one section for the whole operation
            if (std::holds_alternative<toolpath::SectionBegin>(record)) {
                if (g == 0)
                    add(record);
                continue;
            }
            if (!planeSet && (groups[g].plane.tilted() || current.tilted()))
                add(groups[g].plane);
            planeSet = true;
            current = groups[g].plane;
            add(record);
        }
        out.warnings.insert(out.warnings.end(), parts[g].warnings.begin(), parts[g].warnings.end());
    }
    if (current.tilted())
        add(toolpath::WorkingPlane{});
    add(toolpath::SectionEnd{});
    out.counts = ops::countMotions(out.toolpath);
    return out;
}

}  // namespace camwb::document::detail
