// Model::planarFaceRegion: outer and inner wires of planar faces, arcs kept exact, B-spline and
// ellipse edges refitted as lines and arcs within the tolerance (checked against the OCCT curve).
#include "OccShapes.h"

#include "geom/Region.h"

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <GeomAPI_Interpolate.hxx>
#include <GeomAPI_ProjectPointOnCurve.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_Ellipse.hxx>
#include <TColgp_HArray1OfPnt.hxx>

#include <numbers>

namespace camwb::occ {
namespace {

using test::countSegments;
constexpr double kPi = std::numbers::pi;

double roundedRectArea(double w, double h, double r) { return w * h - (4 - kPi) * r * r; }

// A 100 x 80 x 20 plate, a pocket 40 x 30 (R5 corners, floor at Z 15) centred at (50, 40) with a
// round island (R6) at its centre and a square island 6 x 6 at (36, 40), both up to the top.
Model plateWithIslands()
{
    static const Model model = [] {
        TopoDS_Shape pocket = test::roundedBox(30, 25, 15, 70, 55, 21, 5);
        pocket = test::cut(pocket, test::cylinder(50, 40, 6, 14, 22));
        pocket = test::cut(pocket, test::box(33, 37, 14, 39, 43, 22));
        return test::loadShape(test::cut(test::box(0, 0, 0, 100, 80, 20), pocket), "plate-islands");
    }();
    return model;
}

TEST(FaceRegion, PocketFloorHasTheIslandsAsClockwiseHoles)
{
    const Model model = plateWithIslands();
    const int floor = test::zFace(model, 1, 15);
    ASSERT_GT(floor, 0);
    const base::Result<geom::Region> region = model.planarFaceRegion(floor);
    ASSERT_TRUE(region.ok()) << region.error().toString();

    EXPECT_TRUE(region->outer.closed);
    EXPECT_TRUE(region->outer.isContinuous(1e-9));
    EXPECT_NEAR(region->outer.signedArea(), roundedRectArea(40, 30, 5), 1e-6);
    EXPECT_EQ(countSegments(region->outer).arcs, 4);
    EXPECT_EQ(countSegments(region->outer).lines, 4);

    ASSERT_EQ(region->holes.size(), 2u);
    int round = 0, square = 0;
    for (const geom::Profile& hole : region->holes) {
        EXPECT_TRUE(hole.closed);
        EXPECT_TRUE(hole.isContinuous(1e-9));
        EXPECT_LT(hole.signedArea(), 0);  // clockwise
        const test::SegmentCounts counts = countSegments(hole);
        if (counts.arcs > 0) {
            ++round;
            EXPECT_EQ(counts.lines, 0);
            EXPECT_NEAR(hole.signedArea(), -kPi * 36, 1e-6);
            for (const geom::Segment& s : hole.segments) {
                EXPECT_NEAR(s.radius(), 6, 1e-9);
                EXPECT_NEAR(s.center.x, 50, 1e-9);
                EXPECT_NEAR(s.center.y, 40, 1e-9);
                EXPECT_FALSE(s.ccw);
            }
        } else {
            ++square;
            EXPECT_EQ(counts.lines, 4);
            EXPECT_NEAR(hole.signedArea(), -36, 1e-9);
        }
    }
    EXPECT_EQ(round, 1);
    EXPECT_EQ(square, 1);
    // The region excludes the islands: a point in an island is outside, one between them inside.
    EXPECT_FALSE(region->contains({50, 40}));
    EXPECT_FALSE(region->contains({36, 40}));
    EXPECT_TRUE(region->contains({60, 40}));
    EXPECT_NEAR(region->area(), roundedRectArea(40, 30, 5) - kPi * 36 - 36, 1e-6);
}

TEST(FaceRegion, TopFaceAndIslandTops)
{
    const Model model = plateWithIslands();
    const int top = model.topPlanarFace();
    const base::Result<geom::Region> region = model.planarFaceRegion(top);
    ASSERT_TRUE(region.ok()) << region.error().toString();
    EXPECT_NEAR(region->outer.signedArea(), 100 * 80, 1e-9);
    ASSERT_EQ(region->holes.size(), 1u);  // the pocket opening
    EXPECT_NEAR(region->holes[0].signedArea(), -roundedRectArea(40, 30, 5), 1e-6);

    // The island tops are faces of their own at Z 20, without holes.
    int islandTops = 0;
    for (int i = 1; i <= model.faceCount(); ++i) {
        const FaceInfo f = model.face(i);
        if (i == top || !f.planar || f.normal.z < 0.5 || std::abs(f.planeZ - 20) > 1e-9)
            continue;
        const base::Result<geom::Region> island = model.planarFaceRegion(i);
        ASSERT_TRUE(island.ok()) << island.error().toString();
        EXPECT_TRUE(island->holes.empty());
        EXPECT_GT(island->outer.signedArea(), 0);
        EXPECT_NEAR(island->outer.signedArea(), f.areaMm2, 1e-6);
        ++islandTops;
    }
    EXPECT_EQ(islandTops, 2);
}

TEST(FaceRegion, BottomFaceLooksDownButComesOutCounterClockwise)
{
    const Model model = plateWithIslands();
    const int bottom = test::zFace(model, -1, 0);
    const base::Result<geom::Region> region = model.planarFaceRegion(bottom);
    ASSERT_TRUE(region.ok()) << region.error().toString();
    EXPECT_NEAR(region->outer.signedArea(), 100 * 80, 1e-9);
    EXPECT_TRUE(region->holes.empty());
}

TEST(FaceRegion, Errors)
{
    const Model model = plateWithIslands();
    int side = 0, cylindrical = 0;
    for (int i = 1; i <= model.faceCount(); ++i) {
        const FaceInfo f = model.face(i);
        if (f.planar && std::abs(f.normal.z) < 1e-9 && side == 0)
            side = i;
        if (!f.planar && cylindrical == 0)
            cylindrical = i;
    }
    const auto message = [&](int face, double tolerance) {
        const base::Result<geom::Region> r = model.planarFaceRegion(face, tolerance);
        return r.ok() ? std::string("ok") : r.error().message;
    };
    EXPECT_NE(message(side, 0.01).find("is not normal to Z"), std::string::npos);
    EXPECT_NE(message(cylindrical, 0.01).find("is not planar"), std::string::npos);
    EXPECT_NE(message(0, 0.01).find("does not exist"), std::string::npos);
    EXPECT_NE(message(model.faceCount() + 1, 0.01).find("does not exist"), std::string::npos);
    EXPECT_NE(message(model.topPlanarFace(), 0).find("tolerance"), std::string::npos);
    EXPECT_FALSE(Model().planarFaceRegion(1).ok());
}

// A prism 10 high over a planar face bounded by `curve` (from its first to its last point) and a
// straight line closing it (nothing when the curve is closed).
Model prismOver(const Handle(Geom_Curve) & curve, const std::string& name)
{
    BRepBuilderAPI_MakeWire wire(BRepBuilderAPI_MakeEdge(curve).Edge());
    const gp_Pnt a = curve->Value(curve->FirstParameter()), b = curve->Value(curve->LastParameter());
    if (a.Distance(b) > 1e-9)
        wire.Add(BRepBuilderAPI_MakeEdge(b, a).Edge());
    const TopoDS_Face face = BRepBuilderAPI_MakeFace(wire.Wire(), Standard_True).Face();
    return test::loadShape(BRepPrimAPI_MakePrism(face, gp_Vec(0, 0, 10)).Shape(), name);
}

// A wavy open B-spline from (0, 0) to (60, 0) through points above the X axis.
Handle(Geom_BSplineCurve) wavySpline()
{
    const double pts[][2] = {{0, 0}, {8, 12}, {18, 20}, {30, 16}, {40, 24}, {52, 14}, {60, 0}};
    Handle(TColgp_HArray1OfPnt) points = new TColgp_HArray1OfPnt(1, 7);
    for (int i = 0; i < 7; ++i)
        points->SetValue(i + 1, gp_Pnt(pts[i][0], pts[i][1], 0));
    GeomAPI_Interpolate interpolate(points, Standard_False, 1e-9);
    interpolate.Perform();
    return interpolate.Curve();
}

// Both ways within `tolerance`: samples of the curve (raised to the face's Z) to the profile, and
// points of the profile to the curve or the closing line on the X axis.
void expectWithin(const geom::Profile& profile, const Handle(Geom_Curve) & curve, double tolerance, bool closingLine)
{
    constexpr int kSamples = 2000;
    double worstToProfile = 0;
    for (int i = 0; i <= kSamples; ++i) {
        const double u = curve->FirstParameter() + (curve->LastParameter() - curve->FirstParameter()) * i / kSamples;
        const gp_Pnt p = curve->Value(u);
        worstToProfile = std::max(worstToProfile, geom::distanceToProfile({p.X(), p.Y()}, profile));
    }
    EXPECT_LE(worstToProfile, tolerance);

    double worstToCurve = 0;
    for (const base::Vec2 q : geom::discretize(profile, tolerance / 100)) {
        GeomAPI_ProjectPointOnCurve projection(gp_Pnt(q.x, q.y, 0), curve);
        double d = projection.NbPoints() > 0 ? projection.LowerDistance() : 1e9;
        if (closingLine && q.x >= 0 && q.x <= 60)
            d = std::min(d, std::abs(q.y));
        const gp_Pnt a = curve->Value(curve->FirstParameter()), b = curve->Value(curve->LastParameter());
        d = std::min({d, std::hypot(q.x - a.X(), q.y - a.Y()), std::hypot(q.x - b.X(), q.y - b.Y())});
        worstToCurve = std::max(worstToCurve, d);
    }
    EXPECT_LE(worstToCurve, tolerance);
}

TEST(FaceRegion, BSplineEdgeIsRefittedWithinTheTolerance)
{
    const Handle(Geom_BSplineCurve) spline = wavySpline();
    const Model model = prismOver(spline, "bspline-prism");
    const int top = test::zFace(model, 1, 10);
    ASSERT_GT(top, 0);
    for (double tolerance : {0.1, 0.01, 0.001}) {
        SCOPED_TRACE(tolerance);
        const base::Result<geom::Region> region = model.planarFaceRegion(top, tolerance);
        ASSERT_TRUE(region.ok()) << region.error().toString();
        const geom::Profile& outer = region->outer;
        EXPECT_TRUE(outer.isContinuous(1e-9));
        EXPECT_GT(outer.signedArea(), 0);
        EXPECT_TRUE(region->holes.empty());
        expectWithin(outer, spline, tolerance, true);
        // The refit restores arcs: far fewer segments than a polyline within the tolerance.
        EXPECT_GT(countSegments(outer).arcs, 0);

        // The outer profile goes through the same code.
        const base::Result<geom::Profile> profile = model.planarFaceOuterProfile(top, tolerance);
        ASSERT_TRUE(profile.ok());
        EXPECT_EQ(profile->segments.size(), outer.segments.size());
        EXPECT_NEAR(profile->signedArea(), outer.signedArea(), 1e-9);
    }
}

TEST(FaceRegion, EllipseIsRefittedWithinTheTolerance)
{
    const Handle(Geom_Ellipse) ellipse = new Geom_Ellipse(gp_Ax2(gp_Pnt(20, 10, 0), gp::DZ()), 25, 12);
    const Model model = prismOver(ellipse, "ellipse-prism");
    const int top = test::zFace(model, 1, 10);
    ASSERT_GT(top, 0);
    for (double tolerance : {0.05, 0.005}) {
        SCOPED_TRACE(tolerance);
        const base::Result<geom::Region> region = model.planarFaceRegion(top, tolerance);
        ASSERT_TRUE(region.ok()) << region.error().toString();
        EXPECT_TRUE(region->outer.isContinuous(1e-9));
        EXPECT_NEAR(region->outer.signedArea(), kPi * 25 * 12, 2 * kPi * 25 * tolerance);
        expectWithin(region->outer, ellipse, tolerance, false);
        EXPECT_GT(countSegments(region->outer).arcs, 0);
    }
}

}  // namespace
}  // namespace camwb::occ
