// Model::holes and Model::circleEdgeAsHole: vertical cylindrical holes for drilling and helix
// milling. A hole is a full circle of cylindrical faces with material outside; split faces (half
// cylinders) are merged; through or blind is decided by what lies just below the hole's bottom.
#include "occ/Model.h"

#include "occ/detail/ModelData.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRepTools.hxx>
#include <Standard_Failure.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

namespace camwb::occ {
namespace {

constexpr double kPi = std::numbers::pi;
// Faces of one hole: axes and radii equal within this, Z ranges touching within it (mm).
constexpr double kSameMm = 1e-6;

// One cylindrical face with a vertical axis and the material outside.
struct HolePiece {
    int face = 0;
    base::Vec2 center;
    double radius = 0;
    double bottomZ = 0, topZ = 0;
    double sweep = 0;  // radians of the circle this face covers
};

std::optional<HolePiece> holePiece(const TopoDS_Face& face, int index)
{
    BRepAdaptor_Surface surface(face);
    if (surface.GetType() != GeomAbs_Cylinder)
        return std::nullopt;
    const gp_Cylinder cylinder = surface.Cylinder();
    const gp_Ax1 axis = cylinder.Axis();
    if (1 - std::abs(axis.Direction().Z()) >= kZAxisTolerance)
        return std::nullopt;
    double u0, u1, v0, v1;
    BRepTools::UVBounds(face, u0, u1, v0, v1);

    // Material outside: the face's outward normal points towards the axis.
    gp_Pnt p;
    gp_Vec du, dv;
    surface.D1((u0 + u1) / 2, (v0 + v1) / 2, p, du, dv);
    gp_Vec normal = du.Crossed(dv);
    if (face.Orientation() == TopAbs_REVERSED)
        normal.Reverse();
    const gp_Vec radial(p.X() - axis.Location().X(), p.Y() - axis.Location().Y(), 0);
    if (normal.Dot(radial) >= 0)
        return std::nullopt;

    HolePiece piece;
    piece.face = index;
    piece.center = {axis.Location().X(), axis.Location().Y()};
    piece.radius = cylinder.Radius();
    const double za = surface.Value(u0, v0).Z(), zb = surface.Value(u0, v1).Z();
    piece.bottomZ = std::min(za, zb);
    piece.topZ = std::max(za, zb);
    piece.sweep = u1 - u0;
    return piece;
}

bool sameHole(const geom::Hole& hole, const HolePiece& piece)
{
    return distance(hole.center, piece.center) <= kSameMm && std::abs(hole.diameterMm / 2 - piece.radius) <= kSameMm &&
           piece.bottomZ <= hole.topZ + kSameMm && piece.topZ >= hole.bottomZ - kSameMm;
}

// True when material touches the hole's circle just beyond `z` (below for dz < 0, above for dz > 0):
// a floor, a drill point cone or a counterbore shoulder below, a cover above.
bool materialBeyond(BRepClass3d_SolidClassifier& classifier, const geom::Hole& hole, double z, double dz)
{
    // Just inside the circle, so that cones as flat as 0.6 degrees still count as material.
    const double r = hole.diameterMm / 2 - 1e-5;
    constexpr int kSamples = 8;
    for (int i = 0; i < kSamples; ++i) {
        const double a = 2 * kPi * i / kSamples;
        classifier.Perform(gp_Pnt(hole.center.x + r * std::cos(a), hole.center.y + r * std::sin(a), z + dz), 1e-7);
        if (classifier.State() == TopAbs_IN)
            return true;
    }
    return false;
}

}  // namespace

std::vector<geom::Hole> ModelData::holes() const
{
    if (!hasBRep())
        return {};
    struct Candidate {
        geom::Hole hole;
        double sweep = 0;
    };
    std::vector<Candidate> candidates;
    try {
        for (int i = 1; i <= faceCount(); ++i) {
            const std::optional<HolePiece> piece = holePiece(TopoDS::Face(faces(i)), i);
            if (!piece)
                continue;
            auto it = std::find_if(candidates.begin(), candidates.end(),
                                   [&](const Candidate& c) { return sameHole(c.hole, *piece); });
            if (it == candidates.end()) {
                candidates.push_back(
                    {geom::Hole{piece->face, piece->center, 2 * piece->radius, piece->topZ, piece->bottomZ, false},
                     piece->sweep});
                continue;
            }
            it->hole.topZ = std::max(it->hole.topZ, piece->topZ);
            it->hole.bottomZ = std::min(it->hole.bottomZ, piece->bottomZ);
            it->sweep += piece->sweep;
        }

        std::vector<geom::Hole> result;
        BRepClass3d_SolidClassifier classifier(shape);
        constexpr double kProbeMm = 1e-3;
        for (Candidate& c : candidates) {
            // Concave fillets (pocket corners) are partial cylinders: a hole goes all the way round.
            if (c.sweep < 2 * kPi - 1e-6)
                continue;
            // A hole covered above cannot be reached from +Z.
            if (materialBeyond(classifier, c.hole, c.hole.topZ, kProbeMm))
                continue;
            c.hole.through = !materialBeyond(classifier, c.hole, c.hole.bottomZ, -kProbeMm);
            result.push_back(c.hole);
        }
        return result;  // by faceIndex: candidates start at their first face
    } catch (const Standard_Failure&) {
        return {};
    }
}

base::Result<geom::Hole> ModelData::circleEdgeAsHole(int edgeIndex) const
{
    const std::string name = "edge " + std::to_string(edgeIndex);
    if (edgeIndex < 1 || edgeIndex > edgeCount())
        return base::makeError(name + " does not exist (the model has " + std::to_string(edgeCount()) + " edges)");
    try {
        BRepAdaptor_Curve curve(TopoDS::Edge(edges(edgeIndex)));
        if (curve.GetType() != GeomAbs_Circle)
            return base::makeError(name + " is not a circle");
        const gp_Circ circle = curve.Circle();
        if (1 - std::abs(circle.Axis().Direction().Z()) >= kZAxisTolerance)
            return base::makeError(name + " is a circle whose axis is not vertical");
        geom::Hole hole;
        hole.center = {circle.Location().X(), circle.Location().Y()};
        hole.diameterMm = 2 * circle.Radius();
        hole.topZ = hole.bottomZ = circle.Location().Z();
        return hole;
    } catch (const Standard_Failure& e) {
        return base::makeError(name + ": OCCT failure: " + e.GetMessageString());
    }
}

}  // namespace camwb::occ
