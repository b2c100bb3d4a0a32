// writeMouldExamplePart: the three-axis mould teaching part (a drafted cavity with floor fillets, a
// shelf and a spherical dome), built with OCCT draft, fillet and boolean operations.
#include "occ/detail/ModelData.h"

#include "occ/detail/PartBuilders.h"

#include <BRepAdaptor_Surface.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepOffsetAPI_DraftAngle.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <gp_Pln.hxx>

namespace camwb::occ {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDraft = 10 * kPi / 180;  // every cavity wall against the vertical
constexpr double kTopZ = 30, kShelfZ = 20, kFloorZ = 10;
constexpr double kShelfX = 28;  // the shelf's wall on its top

// `shape` with the edges `pick` takes (given the edge's end points) rounded to `radius`.
template <typename Pick> TopoDS_Shape filletEdges(const TopoDS_Shape& shape, double radius, Pick pick, const char* what)
{
    BRepFilletAPI_MakeFillet fillet(shape);
    for (TopExp_Explorer it(shape, TopAbs_EDGE); it.More(); it.Next()) {
        const TopoDS_Edge& edge = TopoDS::Edge(it.Current());
        if (pick(BRep_Tool::Pnt(TopExp::FirstVertex(edge)), BRep_Tool::Pnt(TopExp::LastVertex(edge))))
            fillet.Add(radius, edge);  // the explorer meets each edge twice; Add ignores repeats
    }
    fillet.Build();
    if (!fillet.IsDone())
        throw Standard_Failure((std::string("rounding ") + what + " failed").c_str());
    return fillet.Shape();
}

// The cavity's volume without the shelf: the opening 80 x 60 mm with corners R12 at the top, its
// walls drafted inwards going down (neutral plane at the top) to the floor, the floor edge rounded
// R3. It reaches 1 mm above the top so the cut sees no coplanar faces.
TopoDS_Shape cavityVolume()
{
    const TopoDS_Shape prism = parts::roundedBox(gp_Pnt(10, 10, kFloorZ), gp_Pnt(90, 70, kTopZ + 1), 12);
    BRepOffsetAPI_DraftAngle draft(prism);
    const gp_Pln neutral(gp_Pnt(0, 0, kTopZ), gp::DZ());
    for (TopExp_Explorer it(prism, TopAbs_FACE); it.More(); it.Next()) {
        const TopoDS_Face& face = TopoDS::Face(it.Current());
        BRepAdaptor_Surface surface(face);
        if (surface.GetType() == GeomAbs_Plane && std::abs(surface.Plane().Axis().Direction().Z()) > 0.5)
            continue;  // the floor and the top stay flat
        draft.Add(face, gp::DZ(), -kDraft, neutral);
        if (!draft.AddDone())
            throw Standard_Failure("drafting a cavity wall failed");
    }
    draft.Build();
    if (!draft.IsDone())
        throw Standard_Failure("drafting the cavity walls failed");
    const auto onFloor = [](const gp_Pnt& a, const gp_Pnt& b) {
        return std::abs(a.Z() - kFloorZ) < 1e-6 && std::abs(b.Z() - kFloorZ) < 1e-6;
    };
    return filletEdges(draft.Shape(), 3, onFloor, "the cavity floor");
}

// The shelf left standing at the cavity's -X end: its top at Z 20, its wall facing +X at X 28 on
// its top and drafted like the cavity walls; a prism along Y through the whole block.
TopoDS_Shape shelfVolume()
{
    const double below = kFloorZ - 1;  // reaches into the floor's material
    const double foot = kShelfX + (kShelfZ - below) * std::tan(kDraft);
    BRepBuilderAPI_MakePolygon outline(gp_Pnt(-1, -1, below), gp_Pnt(foot, -1, below), gp_Pnt(kShelfX, -1, kShelfZ),
                                       gp_Pnt(-1, -1, kShelfZ), true);
    const TopoDS_Face profile = BRepBuilderAPI_MakeFace(outline.Wire(), true).Face();
    return BRepPrimAPI_MakePrism(profile, gp_Vec(0, 82, 0)).Shape();
}

// Rounds R3 the edges where the shelf meets the cavity: its top against the walls and its wall
// against the walls and the floor (convex edges of the removed volume); the shelf's own top edge
// at X 28 stays sharp.
TopoDS_Shape roundShelfEdges(const TopoDS_Shape& removed)
{
    const auto onShelfWall = [](const gp_Pnt& p) {
        return std::abs(p.X() - (kShelfX + (kShelfZ - p.Z()) * std::tan(kDraft))) < 1e-6;
    };
    const auto meetsTheCavity = [&](const gp_Pnt& a, const gp_Pnt& b) {
        const bool onShelfTop = std::abs(a.Z() - kShelfZ) < 1e-6 && std::abs(b.Z() - kShelfZ) < 1e-6;
        const bool topEdge = onShelfTop && onShelfWall(a) && onShelfWall(b);
        return !topEdge && (onShelfTop || (onShelfWall(a) && onShelfWall(b)));
    };
    return filletEdges(removed, 3, meetsTheCavity, "the shelf's edges");
}

TopoDS_Shape buildMouldPart()
{
    using parts::cut;
    TopoDS_Shape removed = roundShelfEdges(cut(cavityVolume(), shelfVolume(), "the shelf"));
    // The dome: a sphere R20 about (60, 40, -4), 6 mm above the floor (top at Z 16, base R 14.28).
    const gp_Pnt domeCentre(60, 40, -4);
    removed = cut(removed, BRepPrimAPI_MakeSphere(domeCentre, 20).Shape(), "the dome");
    const TopoDS_Shape block = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), gp_Pnt(100, 80, kTopZ)).Shape();
    const TopoDS_Shape part = cut(block, removed, "the cavity");
    // The dome's foot rounded R2 into the floor (the circle where the sphere meets Z 10).
    const auto domeFoot = [&](const gp_Pnt& a, const gp_Pnt&) {
        return std::abs(a.Z() - kFloorZ) < 1e-6 && std::abs(a.Distance(domeCentre) - 20) < 1e-6;
    };
    return filletEdges(part, 2, domeFoot, "the dome's foot");
}

}  // namespace

base::Status occt::writeMouldExamplePart(const std::string& stepPath)
{
    return detail::writeStep(buildMouldPart, "example-mould", stepPath);
}

}  // namespace camwb::occ
