// writeFiveAxisExamplePart: the five-axis teaching part (inclined faces, a spherical cap, holes
// square to the inclined faces, a boss on one of them, a drafted round boss on another), built with OCCT primitives and
// booleans; writeFiveAxisExampleBlank: the cast blank its job's operations start from.
#include "occ/detail/ModelData.h"

#include "occ/detail/PartBuilders.h"

#include <BRepAlgoAPI_Common.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>

namespace camwb::occ {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kSlopeDeg = 30;  // the inclined faces against the horizontal
constexpr double kDraftDeg = 15;  // the drafted boss' wall against its axis

// The outward normal and the centre of the inclined face on the side `quarter` x 90 degrees from
// +X about Z.
gp_Dir sideNormal(int quarter)
{
    const double s = std::sin(kSlopeDeg * kPi / 180), c = std::cos(kSlopeDeg * kPi / 180);
    const double a = quarter * kPi / 2;
    return gp_Dir(s * std::cos(a), s * std::sin(a), c);
}

gp_Pnt sideCentre(int quarter, double along = 0)
{
    // Half way up the face (Z 27.5), 7.5 / tan(30) in from the block's side at X 40.
    const double r = 40 - 7.5 / std::tan(kSlopeDeg * kPi / 180);
    const double a = quarter * kPi / 2;
    return gp_Pnt(r * std::cos(a) - along * std::sin(a), r * std::sin(a) + along * std::cos(a), 27.5);
}

TopoDS_Shape fuse(const TopoDS_Shape& a, const TopoDS_Shape& b, const char* what)
{
    BRepAlgoAPI_Fuse result(a, b);
    if (!result.IsDone())
        throw Standard_Failure((std::string("adding ") + what + " failed").c_str());
    return result.Shape();
}

// The inclined block with the cap: what part and blank have in common.
TopoDS_Shape buildInclinedBlock()
{
    using parts::cut;
    TopoDS_Shape part = BRepPrimAPI_MakeBox(gp_Pnt(-40, -40, 0), gp_Pnt(40, 40, 35)).Shape();
    // Four half spaces cut the faces inclined 30 degrees, each through the block's top edge at Z 20.
    for (int quarter = 0; quarter < 4; ++quarter) {
        const gp_Dir n = sideNormal(quarter);
        const gp_Dir along(-std::sin(quarter * kPi / 2), std::cos(quarter * kPi / 2), 0);
        const double a = quarter * kPi / 2;
        const gp_Pnt onEdge(40 * std::cos(a), 40 * std::sin(a), 20);
        const gp_Ax2 frame(onEdge, n, along);
        const gp_Vec shift = gp_Vec(frame.XDirection()) * -200 + gp_Vec(frame.YDirection()) * -200;
        const gp_Ax2 corner(onEdge.Translated(shift), n, along);
        part = cut(part, BRepPrimAPI_MakeBox(corner, 400, 400, 200).Shape(), "an inclined face");
    }
    // The cap: a sphere R20 about (0, 0, 20) above the top face at Z 35 (5 high, base R 13.23).
    const TopoDS_Shape sphere = BRepPrimAPI_MakeSphere(gp_Pnt(0, 0, 20), 20).Shape();
    const TopoDS_Shape above = BRepPrimAPI_MakeBox(gp_Pnt(-25, -25, 34), gp_Pnt(25, 25, 45)).Shape();
    BRepAlgoAPI_Common cap(sphere, above);
    if (!cap.IsDone())
        throw Standard_Failure("making the spherical cap failed");
    return fuse(part, cap.Shape(), "the spherical cap");
}

// A box on the -X face, 12 mm to the side of its centre: `width` along the face's horizontal
// edges, `length` up the slope, from 1 mm under the face to `height` above it.
TopoDS_Shape padOnMinusXFace(double width, double length, double height)
{
    const gp_Dir n = sideNormal(2);
    const gp_Dir across(0, -1, 0);  // along the face's horizontal edges
    const gp_Ax2 frame(sideCentre(2, -12), n, across);
    const gp_Vec shift =
        gp_Vec(frame.XDirection()) * (-width / 2) + gp_Vec(frame.YDirection()) * (-length / 2) - gp_Vec(n) * 1;
    const gp_Ax2 corner(sideCentre(2, -12).Translated(shift), n, across);
    return BRepPrimAPI_MakeBox(corner, width, length, height + 1).Shape();
}

// The drafted boss' place on the +X face, 14 mm to the side of its hole, 1 mm under the face.
gp_Ax2 coneAxis()
{
    const gp_Dir n = sideNormal(0);
    return gp_Ax2(sideCentre(0, 14).Translated(gp_Vec(n) * -1), n);
}

TopoDS_Shape buildFiveAxisPart()
{
    using parts::cut;
    TopoDS_Shape part = buildInclinedBlock();
    // A boss 10 x 8 x 3 mm on the -X face, 12 mm to the side of its centre (the contour's feature).
    {
        const gp_Dir n = sideNormal(2);
        const gp_Dir width(0, -1, 0);  // along the face's horizontal edges
        const gp_Ax2 frame(sideCentre(2, -12), n, width);
        const gp_Vec shift = gp_Vec(frame.XDirection()) * -5 + gp_Vec(frame.YDirection()) * -4 - gp_Vec(n) * 1;
        const gp_Ax2 corner(sideCentre(2, -12).Translated(shift), n, width);
        part = fuse(part, BRepPrimAPI_MakeBox(corner, 10, 8, 4).Shape(), "the boss");
    }
    // Holes D6, 8 deep, square to each inclined face (the -X one 12 mm to the other side).
    for (int quarter = 0; quarter < 4; ++quarter) {
        const gp_Dir n = sideNormal(quarter);
        const gp_Pnt centre = sideCentre(quarter, quarter == 2 ? 12 : 0);
        const gp_Pnt start = centre.Translated(gp_Vec(n) * 1);
        part = cut(part, BRepPrimAPI_MakeCylinder(gp_Ax2(start, n.Reversed()), 3, 9).Shape(), "a hole");
    }
    // A drafted round boss on the +X face, 14 mm to the side of its hole (the swarf operation's
    // cone): R5.5 where it meets the face, 5 high, its wall drafted 15 degrees. Added last, so the
    // faces of the features above keep their numbers.
    {
        const double draft = std::tan(kDraftDeg * kPi / 180);
        const TopoDS_Shape cone = BRepPrimAPI_MakeCone(coneAxis(), 5.5 + draft, 5.5 - 5 * draft, 6).Shape();
        part = fuse(part, cone, "the drafted boss");
    }
    return part;
}

// The blank as cast: the inclined block and cap without the holes (they are drilled); where the
// boss stands, a pad 3 mm high (the boss' height) reaching 4 mm round it (5.7 mm at its corners), which the contour's
// two steps of a D6 cutter take off entirely; where the drafted boss stands, a round stub R6 and 5 mm high, 0.5 mm over
// the cone's foot and 1.84 mm over its top, which the swarf pass's flank takes off.
TopoDS_Shape buildFiveAxisBlank()
{
    TopoDS_Shape blank = buildInclinedBlock();
    blank = fuse(blank, padOnMinusXFace(18, 16, 3), "the boss' pad");
    return fuse(blank, BRepPrimAPI_MakeCylinder(coneAxis(), 6, 6).Shape(), "the drafted boss' stub");
}

}  // namespace

base::Status occt::writeFiveAxisExamplePart(const std::string& stepPath)
{
    return detail::writeStep(buildFiveAxisPart, "example-five-axis", stepPath);
}

base::Status occt::writeFiveAxisExampleBlank(const std::string& stepPath)
{
    return detail::writeStep(buildFiveAxisBlank, "example-five-axis-blank", stepPath);
}

}  // namespace camwb::occ
