// Edges and wires in an XY plane as lines and arcs (detail/EdgeProfile.h): the one place that
// decides how a model curve becomes geom segments.
#include "occ/detail/EdgeProfile.h"

#include "geom/ArcFit.h"
#include "occ/detail/ModelData.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <GCPnts_QuasiUniformDeflection.hxx>
#include <TopExp.hxx>
#include <TopoDS_Vertex.hxx>

#include <algorithm>
#include <cmath>
#include <vector>

namespace camwb::occ {
namespace {

using base::Vec2;
using geom::Segment;

// Sampling within a quarter and fitting within half the tolerance keeps the result within 3/4 of it.
constexpr double kSampleShare = 0.25;
constexpr double kFitShare = 0.5;

Vec2 edgeXY(const gp_Pnt& p) { return {p.X(), p.Y()}; }

void appendFitted(geom::Profile& profile, const std::vector<Vec2>& polyline, double toleranceMm)
{
    const geom::Profile fitted = geom::fitLinesAndArcs(polyline, false, toleranceMm * kFitShare);
    if (fitted.empty()) {
        for (std::size_t i = 0; i + 1 < polyline.size(); ++i)
            if (distance(polyline[i], polyline[i + 1]) > 0)
                profile.segments.push_back(Segment::line(polyline[i], polyline[i + 1]));
        return;
    }
    profile.segments.insert(profile.segments.end(), fitted.segments.begin(), fitted.segments.end());
}

void appendSampled(geom::Profile& profile, const BRepAdaptor_Curve& curve, bool reversed, Vec2 from, Vec2 to,
                   double toleranceMm)
{
    GCPnts_QuasiUniformDeflection points(curve, toleranceMm * kSampleShare, curve.FirstParameter(),
                                         curve.LastParameter());
    std::vector<Vec2> polyline;
    if (points.IsDone() && points.NbPoints() >= 2) {
        for (int i = 1; i <= points.NbPoints(); ++i)
            polyline.push_back(edgeXY(points.Value(i)));
        if (reversed)
            std::reverse(polyline.begin(), polyline.end());
    }
    if (polyline.size() < 2)
        polyline = {from, to};
    polyline.front() = from;
    polyline.back() = to;
    if (polyline.size() >= 4 && distance(from, to) <= 1e-9) {
        // A closed curve: fit the two halves, so that no fitted piece starts where it ends.
        const std::size_t mid = polyline.size() / 2;
        appendFitted(profile, std::vector<Vec2>(polyline.begin(), polyline.begin() + mid + 1), toleranceMm);
        appendFitted(profile, std::vector<Vec2>(polyline.begin() + mid, polyline.end()), toleranceMm);
        return;
    }
    appendFitted(profile, polyline, toleranceMm);
}

}  // namespace

void appendEdge(geom::Profile& profile, const TopoDS_Edge& edge, bool reversed, Vec2 from, Vec2 to, double toleranceMm)
{
    BRepAdaptor_Curve curve(edge);
    const GeomAbs_CurveType type = curve.GetType();

    if (type == GeomAbs_Line) {
        if (distance(from, to) > 0)
            profile.segments.push_back(Segment::line(from, to));
        return;
    }
    if (type == GeomAbs_Circle) {
        const gp_Circ circle = curve.Circle();
        const double axisZ = circle.Axis().Direction().Z();
        if (1 - std::abs(axisZ) < kZAxisTolerance) {
            // Parameters run counter-clockwise about the circle's axis; the edge may run against them.
            const bool ccw = (axisZ > 0) != reversed;
            const Vec2 centre = edgeXY(circle.Location());
            if (distance(from, to) <= 1e-9) {
                // A full circle: two half arcs, so that no segment starts where it ends.
                const Vec2 opposite = centre * 2 - from;
                profile.segments.push_back(Segment::arc(from, opposite, centre, ccw));
                profile.segments.push_back(Segment::arc(opposite, to, centre, ccw));
            } else {
                profile.segments.push_back(Segment::arc(from, to, centre, ccw));
            }
            return;
        }
    }
    appendSampled(profile, curve, reversed, from, to, toleranceMm);
}

base::Result<geom::Profile> wireProfile(const TopoDS_Wire& wire, const TopoDS_Face& face, double toleranceMm)
{
    geom::Profile profile;
    profile.closed = true;
    for (BRepTools_WireExplorer it(wire, face); it.More(); it.Next()) {
        const TopoDS_Edge& edge = it.Current();
        if (BRep_Tool::Degenerated(edge))
            continue;
        // Oriented vertices: the first is where the edge starts in the wire's direction.
        const TopoDS_Vertex first = TopExp::FirstVertex(edge, Standard_True);
        const TopoDS_Vertex last = TopExp::LastVertex(edge, Standard_True);
        if (first.IsNull() || last.IsNull())
            return base::makeError("a wire has an edge without vertices");
        appendEdge(profile, edge, edge.Orientation() == TopAbs_REVERSED, edgeXY(BRep_Tool::Pnt(first)),
                   edgeXY(BRep_Tool::Pnt(last)), toleranceMm);
    }
    if (profile.empty())
        return base::makeError("a wire has no edges");
    return profile;
}

}  // namespace camwb::occ
