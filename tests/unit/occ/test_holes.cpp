// Model::holes and Model::circleEdgeAsHole: through, blind (flat and drill-point bottoms),
// counterbored, split into half cylinders, covered, horizontal; fillets that are not holes.
#include "OccShapes.h"

#include <BRepAdaptor_Surface.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <ShapeUpgrade_ShapeDivideClosed.hxx>
#include <TopTools_IndexedMapOfShape.hxx>

#include <cmath>
#include <numbers>

namespace camwb::occ {
namespace {

// 80 x 40 x 20 with R5 corners and a pocket with R4 corners (fillets that are not holes), and:
// a through hole D8 at (10, 20); a flat blind hole D6 10 deep at (25, 20); a drill-point blind hole
// D6 8 deep to the shoulder at (40, 10); a counterbore D12 x 5 over a through hole D6 at (60, 20);
// a hole D4 from below, covered at the top, at (40, 32); a horizontal hole D4 along X at y = 10, z = 5.
TopoDS_Shape holesBlock()
{
    TopoDS_Shape part = test::roundedBox(0, 0, 0, 80, 40, 20, 5);
    part = test::cut(part, test::roundedBox(18, 27, 15, 34, 38, 21, 4));
    part = test::cut(part, test::cylinder(10, 20, 4, -1, 21));
    part = test::cut(part, test::cylinder(25, 20, 3, 10, 21));
    const double coneHeight = 3 / std::tan(59.0 * std::numbers::pi / 180);  // 118 degree drill point
    part = test::cut(
        part,
        test::fuse(test::cylinder(40, 10, 3, 12, 21),
                   BRepPrimAPI_MakeCone(gp_Ax2(gp_Pnt(40, 10, 12 - coneHeight), gp::DZ()), 0, 3, coneHeight).Shape()));
    part = test::cut(part, test::cylinder(60, 20, 6, 15, 21));
    part = test::cut(part, test::cylinder(60, 20, 3, -1, 21));
    part = test::cut(part, test::cylinder(40, 32, 2, -1, 8));
    part = test::cut(part, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(-1, 10, 5), gp::DX()), 2, 82).Shape());
    return part;
}

const geom::Hole* holeAt(const std::vector<geom::Hole>& holes, double x, double y, double diameter)
{
    for (const geom::Hole& h : holes)
        if (distance(h.center, base::Vec2{x, y}) < 1e-9 && std::abs(h.diameterMm - diameter) < 1e-9)
            return &h;
    return nullptr;
}

void expectHole(const std::vector<geom::Hole>& holes, double x, double y, double diameter, double top, double bottom,
                bool through)
{
    SCOPED_TRACE("hole D" + std::to_string(diameter) + " at " + std::to_string(x) + ", " + std::to_string(y));
    const geom::Hole* h = holeAt(holes, x, y, diameter);
    ASSERT_NE(h, nullptr);
    EXPECT_GT(h->faceIndex, 0);
    EXPECT_NEAR(h->topZ, top, 1e-9);
    EXPECT_NEAR(h->bottomZ, bottom, 1e-9);
    EXPECT_EQ(h->through, through);
}

TEST(Holes, ThroughBlindPointedCounterbored)
{
    const Model model = test::loadShape(holesBlock(), "holes-block");
    const std::vector<geom::Hole> holes = model.holes();
    ASSERT_EQ(holes.size(), 5u);
    expectHole(holes, 10, 20, 8, 20, 0, true);
    expectHole(holes, 25, 20, 6, 20, 10, false);
    expectHole(holes, 40, 10, 6, 20, 12, false);
    expectHole(holes, 60, 20, 12, 20, 15, false);  // the shoulder closes it
    expectHole(holes, 60, 20, 6, 15, 0, true);
    for (std::size_t i = 1; i < holes.size(); ++i)
        EXPECT_LT(holes[i - 1].faceIndex, holes[i].faceIndex);
    for (const geom::Hole& h : holes)
        EXPECT_FALSE(model.face(h.faceIndex).planar);
}

// The cylindrical faces of radius `radius` around (x, y), by their index in the loaded model.
std::vector<int> cylinderFaces(const TopoDS_Shape& shape, double x, double y, double radius)
{
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(shape, TopAbs_FACE, faces);
    std::vector<int> result;
    for (int i = 1; i <= faces.Extent(); ++i) {
        BRepAdaptor_Surface s(TopoDS::Face(faces(i)));
        if (s.GetType() == GeomAbs_Cylinder && std::abs(s.Cylinder().Radius() - radius) < 1e-9 &&
            std::abs(s.Cylinder().Location().X() - x) < 1e-9 && std::abs(s.Cylinder().Location().Y() - y) < 1e-9)
            result.push_back(i);
    }
    return result;
}

TEST(Holes, HalfCylindersAreOneHole)
{
    // Other CAD systems write closed faces as halves: split every closed face of the block.
    ShapeUpgrade_ShapeDivideClosed divide(holesBlock());
    divide.SetNbSplitPoints(1);
    divide.Perform();
    const TopoDS_Shape split = divide.Result();
    const Model model = test::loadShape(split, "holes-block-split");
    const Model whole = test::loadShape(holesBlock(), "holes-block-whole");
    ASSERT_GT(model.faceCount(), whole.faceCount());

    const std::vector<geom::Hole> holes = model.holes();
    ASSERT_EQ(holes.size(), 5u);
    expectHole(holes, 10, 20, 8, 20, 0, true);
    expectHole(holes, 25, 20, 6, 20, 10, false);
    expectHole(holes, 40, 10, 6, 20, 12, false);
    expectHole(holes, 60, 20, 12, 20, 15, false);
    expectHole(holes, 60, 20, 6, 15, 0, true);
    const std::vector<int> halves = cylinderFaces(split, 10, 20, 4);
    ASSERT_EQ(halves.size(), 2u);
    EXPECT_EQ(holeAt(holes, 10, 20, 8)->faceIndex, std::min(halves[0], halves[1]));
}

TEST(Holes, NoneInAPlainBlockOrAnStlOrAnEmptyModel)
{
    EXPECT_TRUE(test::loadShape(test::roundedBox(0, 0, 0, 30, 20, 10, 3), "plain").holes().empty());
    EXPECT_TRUE(Model().holes().empty());
}

TEST(CircleEdgeAsHole, VerticalCirclesOnlyAtTheirZ)
{
    const Model model = test::loadShape(holesBlock(), "holes-block-edges");
    int topCircle = 0, horizontalCircle = 0, line = 0;
    for (int i = 1; i <= model.edgeCount(); ++i) {
        const EdgeInfo e = model.edge(i);
        if (e.curve == EdgeInfo::Curve::Circle && std::abs(e.start.z - 20) < 1e-9 &&
            std::abs(distance(e.start.xy(), base::Vec2{10, 20}) - 4) < 1e-9)
            topCircle = i;
        if (e.curve == EdgeInfo::Curve::Circle && std::abs(e.start.x) < 1e-9 &&
            std::abs(std::hypot(e.start.y - 10, e.start.z - 5) - 2) < 1e-9)
            horizontalCircle = i;
        if (e.curve == EdgeInfo::Curve::Line && line == 0)
            line = i;
    }
    ASSERT_GT(topCircle, 0);
    ASSERT_GT(horizontalCircle, 0);
    ASSERT_GT(line, 0);

    const base::Result<geom::Hole> hole = model.circleEdgeAsHole(topCircle);
    ASSERT_TRUE(hole.ok()) << hole.error().toString();
    EXPECT_NEAR(hole->center.x, 10, 1e-9);
    EXPECT_NEAR(hole->center.y, 20, 1e-9);
    EXPECT_NEAR(hole->diameterMm, 8, 1e-9);
    EXPECT_NEAR(hole->topZ, 20, 1e-9);
    EXPECT_NEAR(hole->bottomZ, 20, 1e-9);
    EXPECT_FALSE(hole->through);
    EXPECT_EQ(hole->faceIndex, 0);

    const auto message = [&](int edge) {
        const base::Result<geom::Hole> r = model.circleEdgeAsHole(edge);
        return r.ok() ? std::string("ok") : r.error().message;
    };
    EXPECT_EQ(message(line), "edge " + std::to_string(line) + " is not a circle");
    EXPECT_EQ(message(horizontalCircle),
              "edge " + std::to_string(horizontalCircle) + " is a circle whose axis is not vertical");
    EXPECT_NE(message(0).find("does not exist"), std::string::npos);
    EXPECT_NE(message(model.edgeCount() + 1).find("does not exist"), std::string::npos);
}

}  // namespace
}  // namespace camwb::occ
