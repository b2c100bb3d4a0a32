// Model::edge and Model::edgeChains: the model's edges, and picked edges chained end to end into
// profiles in XY (open or closed) for contours along edges.
#include "occ/Model.h"

#include "occ/detail/EdgeProfile.h"
#include "occ/detail/ModelData.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepBndLib.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Vertex.hxx>

#include <cmath>
#include <deque>
#include <set>
#include <string>
#include <vector>

namespace camwb::occ {
namespace {

// Edge ends closer than this (mm, in 3D) are one point of a chain; an edge whose Z varies by more
// is not horizontal.
constexpr double kCoincidentMm = 1e-6;

base::Vec3 vec3(const gp_Pnt& p) { return {p.X(), p.Y(), p.Z()}; }

std::string edgeName(int index) { return "edge " + std::to_string(index); }

struct ChainEdge {
    int index = 0;  // the model's edge index
    TopoDS_Edge edge;
    int node[2] = {0, 0};  // chain points at the start and end (parameter direction)
};

struct Step {
    int item = 0;
    bool reversed = false;
};

// The chain points, merging positions within kCoincidentMm.
class Nodes {
public:
    int find(const base::Vec3& p)
    {
        for (std::size_t i = 0; i < m_points.size(); ++i)
            if ((m_points[i] - p).length() <= kCoincidentMm)
                return static_cast<int>(i);
        m_points.push_back(p);
        m_edges.emplace_back();
        return static_cast<int>(m_points.size() - 1);
    }
    const base::Vec3& point(int node) const { return m_points[static_cast<std::size_t>(node)]; }
    std::vector<int>& edgesAt(int node) { return m_edges[static_cast<std::size_t>(node)]; }
    std::size_t size() const { return m_points.size(); }

private:
    std::vector<base::Vec3> m_points;
    std::vector<std::vector<int>> m_edges;  // items touching each node (twice for a closed edge)
};

base::Status checkHorizontal(const TopoDS_Edge& edge, int index, const base::Vec3& a, const base::Vec3& b)
{
    if (BRep_Tool::Degenerated(edge))
        return base::makeError(edgeName(index) + " is degenerated (a point)");
    Bnd_Box box;
    BRepBndLib::AddOptimal(edge, box, Standard_False, Standard_False);
    double x0, y0, z0, x1, y1, z1;
    box.Get(x0, y0, z0, x1, y1, z1);
    if (z1 - z0 <= kCoincidentMm)
        return base::Status::success();
    const base::Vec2 d = a.xy() - b.xy();
    if (d.length() <= kCoincidentMm && std::abs(a.z - b.z) > kCoincidentMm)
        return base::makeError(edgeName(index) + " is vertical: only edges in an XY plane can be chained");
    return base::makeError(edgeName(index) + " does not lie in an XY plane (its Z runs from " + std::to_string(z0) +
                           " to " + std::to_string(z1) + ")");
}

// Walks from `node` along unvisited items, appending (or prepending) the steps.
int walk(Nodes& nodes, std::vector<ChainEdge>& items, std::vector<bool>& used, int node, int stopAt,
         std::deque<Step>& steps, bool forward)
{
    for (;;) {
        int next = -1;
        for (int item : nodes.edgesAt(node))
            if (!used[static_cast<std::size_t>(item)]) {
                next = item;
                break;
            }
        if (next < 0)
            return node;
        used[static_cast<std::size_t>(next)] = true;
        const ChainEdge& e = items[static_cast<std::size_t>(next)];
        // Forward walks leave `node` along the edge; backward walks arrive at it.
        const bool reversed = forward ? e.node[0] != node : e.node[1] != node;
        if (forward)
            steps.push_back({next, reversed});
        else
            steps.push_front({next, reversed});
        node = forward == !reversed ? e.node[1] : e.node[0];
        if (node == stopAt)
            return node;
    }
}

}  // namespace

EdgeInfo describeEdge(const TopoDS_Edge& edge, int index)
{
    EdgeInfo info;
    info.index = index;
    try {
        TopoDS_Vertex first, last;
        TopExp::Vertices(edge, first, last);  // in the parameter direction
        if (!first.IsNull())
            info.start = vec3(BRep_Tool::Pnt(first));
        if (!last.IsNull())
            info.end = vec3(BRep_Tool::Pnt(last));
        if (BRep_Tool::Degenerated(edge))
            return info;
        BRepAdaptor_Curve curve(edge);
        switch (curve.GetType()) {
        case GeomAbs_Line:
            info.curve = EdgeInfo::Curve::Line;
            break;
        case GeomAbs_Circle:
            info.curve = EdgeInfo::Curve::Circle;
            break;
        case GeomAbs_BSplineCurve:
        case GeomAbs_BezierCurve:
            info.curve = EdgeInfo::Curve::BSpline;
            break;
        default:
            break;
        }
        info.lengthMm = GCPnts_AbscissaPoint::Length(curve);
    } catch (const Standard_Failure&) {
        // An edge OCCT cannot evaluate stays listed (indices must not shift) but undescribed.
    }
    return info;
}

base::Result<std::vector<geom::Profile>> ModelData::edgeChains(const std::vector<int>& edgeIndices,
                                                               double toleranceMm) const
{
    if (!(toleranceMm > 0))
        return base::makeError("the tolerance must be positive");
    if (edgeIndices.empty())
        return base::makeError("no edges selected");
    std::set<int> seen;
    for (int index : edgeIndices) {
        if (index < 1 || index > edgeCount())
            return base::makeError(edgeName(index) + " does not exist (the model has " + std::to_string(edgeCount()) +
                                   " edges)");
        if (!seen.insert(index).second)
            return base::makeError(edgeName(index) + " is selected twice");
    }
    try {
        Nodes nodes;
        std::vector<ChainEdge> items;
        for (int index : edgeIndices) {
            ChainEdge item{index, TopoDS::Edge(edges(index)), {0, 0}};
            TopoDS_Vertex first, last;
            TopExp::Vertices(item.edge, first, last);
            if (first.IsNull() || last.IsNull())
                return base::makeError(edgeName(index) + " has no end points");
            const base::Vec3 a = vec3(BRep_Tool::Pnt(first)), b = vec3(BRep_Tool::Pnt(last));
            if (base::Status flat = checkHorizontal(item.edge, index, a, b); !flat)
                return flat.error();
            item.node[0] = nodes.find(a);
            item.node[1] = nodes.find(b);
            const int at = static_cast<int>(items.size());
            nodes.edgesAt(item.node[0]).push_back(at);
            nodes.edgesAt(item.node[1]).push_back(at);
            items.push_back(item);
        }
        for (std::size_t n = 0; n < nodes.size(); ++n) {
            const std::vector<int>& at = nodes.edgesAt(static_cast<int>(n));
            if (at.size() <= 2)
                continue;
            std::string names;
            for (std::size_t k = 0; k < at.size(); ++k)
                names += (k == 0               ? ""
                          : k + 1 == at.size() ? " and "
                                               : ", ") +
                         std::to_string(items[static_cast<std::size_t>(at[k])].index);
            const base::Vec3 p = nodes.point(static_cast<int>(n));
            return base::makeError("edges " + names + " meet at one point (" + std::to_string(p.x) + ", " +
                                   std::to_string(p.y) + ", " + std::to_string(p.z) + "): a chain cannot branch");
        }

        std::vector<geom::Profile> chains;
        std::vector<bool> used(items.size(), false);
        for (std::size_t i = 0; i < items.size(); ++i) {
            if (used[i])
                continue;
            used[i] = true;
            std::deque<Step> steps{{static_cast<int>(i), false}};
            const int start = items[i].node[0];
            bool closed = items[i].node[1] == start;
            if (!closed)
                closed = walk(nodes, items, used, items[i].node[1], start, steps, true) == start;
            if (!closed)
                walk(nodes, items, used, start, -1, steps, false);

            geom::Profile profile;
            profile.closed = closed;
            for (const Step& step : steps) {
                const ChainEdge& e = items[static_cast<std::size_t>(step.item)];
                const base::Vec2 from = nodes.point(e.node[step.reversed ? 1 : 0]).xy();
                const base::Vec2 to = nodes.point(e.node[step.reversed ? 0 : 1]).xy();
                appendEdge(profile, e.edge, step.reversed, from, to, toleranceMm);
            }
            chains.push_back(std::move(profile));
        }
        return chains;
    } catch (const Standard_Failure& e) {
        return base::makeError(std::string("edge chains: OCCT failure: ") + e.GetMessageString());
    }
}

}  // namespace camwb::occ
