// Model::planarFaceOuterProfile: the outer wire of a face lying in an XY plane, as a geom::Profile.
// Circles stay arcs (centre and direction from the curve and the edge orientation); other curves
// are split into lines within the requested tolerance.
#include "occ/Model.h"

#include "occ/detail/ModelData.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <GCPnts_QuasiUniformDeflection.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace camwb::occ {
namespace {

using base::Vec2;
using geom::Segment;

Vec2 xy(const gp_Pnt& p) { return {p.X(), p.Y()}; }

// Appends one edge, travelled in its wire orientation from `from` to `to` (its vertices, so that
// consecutive segments meet exactly).
void appendEdge(geom::Profile& profile, const TopoDS_Edge& edge, Vec2 from, Vec2 to, double toleranceMm)
{
    BRepAdaptor_Curve curve(edge);
    const bool reversed = edge.Orientation() == TopAbs_REVERSED;
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
            const Vec2 centre = xy(circle.Location());
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

    GCPnts_QuasiUniformDeflection points(curve, toleranceMm, curve.FirstParameter(), curve.LastParameter());
    std::vector<Vec2> polyline;
    if (points.IsDone() && points.NbPoints() >= 2) {
        for (int i = 1; i <= points.NbPoints(); ++i)
            polyline.push_back(xy(points.Value(i)));
        if (reversed)
            std::reverse(polyline.begin(), polyline.end());
    }
    if (polyline.size() < 2)
        polyline = {from, to};
    polyline.front() = from;
    polyline.back() = to;
    for (std::size_t i = 0; i + 1 < polyline.size(); ++i)
        if (distance(polyline[i], polyline[i + 1]) > 0)
            profile.segments.push_back(Segment::line(polyline[i], polyline[i + 1]));
}

base::Result<geom::Profile> outerProfile(const TopoDS_Face& face, double toleranceMm)
{
    const TopoDS_Wire wire = BRepTools::OuterWire(face);
    if (wire.IsNull())
        return base::makeError("the face has no outer wire");
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
            return base::makeError("the outer wire has an edge without vertices");
        appendEdge(profile, edge, xy(BRep_Tool::Pnt(first)), xy(BRep_Tool::Pnt(last)), toleranceMm);
    }
    if (profile.empty())
        return base::makeError("the outer wire has no edges");
    // The wire runs counter-clockwise about the face normal; faces looking down come out clockwise.
    if (profile.signedArea() < 0)
        profile = profile.reversed();
    return profile;
}

}  // namespace

base::Result<geom::Profile> Model::planarFaceOuterProfile(int faceIndex, double toleranceMm) const
{
    if (faceIndex < 1 || faceIndex > faceCount())
        return base::makeError("face " + std::to_string(faceIndex) + " does not exist (the model has " +
                               std::to_string(faceCount()) + " faces)");
    const FaceInfo info = face(faceIndex);
    if (!info.planar)
        return base::makeError("face " + std::to_string(faceIndex) + " is not planar");
    if (1 - std::abs(info.normal.z) >= kZAxisTolerance)
        return base::makeError("face " + std::to_string(faceIndex) + " is not normal to Z");
    if (!(toleranceMm > 0))
        return base::makeError("the tolerance must be positive");
    try {
        base::Result<geom::Profile> profile = outerProfile(TopoDS::Face(m_data->faces(faceIndex)), toleranceMm);
        if (!profile)
            return base::makeError("face " + std::to_string(faceIndex) + ": " + profile.error().message);
        return profile;
    } catch (const Standard_Failure& e) {
        return base::makeError("face " + std::to_string(faceIndex) + ": OCCT failure: " + e.GetMessageString());
    }
}

}  // namespace camwb::occ
