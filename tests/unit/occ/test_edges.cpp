// Model::edge and Model::edgeChains: edges listed with their kind and ends; picked edges chained
// into open and closed XY profiles in the direction of the first listed edge; every refusal.
#include "OccShapes.h"

#include "geom/Region.h"

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <GeomAPI_Interpolate.hxx>
#include <TColgp_HArray1OfPnt.hxx>

#include <algorithm>
#include <numbers>
#include <random>

namespace camwb::occ {
namespace {

using Curve = EdgeInfo::Curve;
constexpr double kPi = std::numbers::pi;

// 50 x 30 x 10 with R4 vertical edges and a through hole R3 at (25, 15).
Model roundedBlock()
{
    static const Model model = test::loadShape(
        test::cut(test::roundedBox(0, 0, 0, 50, 30, 10, 4), test::cylinder(25, 15, 3, -1, 11)), "rounded-block");
    return model;
}

// The edges with both ends at `z` that are not on the circle around (25, 15).
std::vector<int> outlineEdgesAt(const Model& model, double z)
{
    std::vector<int> result;
    for (int i = 1; i <= model.edgeCount(); ++i) {
        const EdgeInfo e = model.edge(i);
        if (std::abs(e.start.z - z) < 1e-9 && std::abs(e.end.z - z) < 1e-9 &&
            distance(e.start.xy(), base::Vec2{25, 15}) > 3.5)
            result.push_back(i);
    }
    return result;
}

bool near(base::Vec2 a, base::Vec2 b) { return distance(a, b) < 1e-9; }

// The edges as exactly one chain, continuous within 1e-9 (an empty profile after a failure).
geom::Profile oneChain(const Model& model, const std::vector<int>& edges, double tolerance = 0.01)
{
    const auto chains = model.edgeChains(edges, tolerance);
    if (!chains.ok()) {
        ADD_FAILURE() << chains.error().toString();
        return {};
    }
    EXPECT_EQ(chains->size(), 1u);
    EXPECT_TRUE(chains->front().isContinuous(1e-9));
    return chains->front();
}

TEST(Edges, ListedWithKindEndsAndLength)
{
    const Model model = roundedBlock();
    // Per level 4 lines + 4 arcs + the hole's circle, and 4 + 1 vertical edges (corner seams and hole seam).
    EXPECT_EQ(model.edgeCount(), 2 * 9 + 4 + 4 + 1);
    int lines = 0, circles = 0;
    for (int i = 1; i <= model.edgeCount(); ++i) {
        const EdgeInfo e = model.edge(i);
        EXPECT_EQ(e.index, i);
        EXPECT_GT(e.lengthMm, 0);
        if (e.curve == Curve::Line) {
            ++lines;
            EXPECT_NEAR(e.lengthMm, (e.end - e.start).length(), 1e-9);
        } else if (e.curve == Curve::Circle) {
            ++circles;
        }
    }
    EXPECT_EQ(lines, 2 * 4 + 4 + 4 + 1);
    EXPECT_EQ(circles, 2 * 4 + 2);
    EXPECT_EQ(model.edge(0).index, 0);
    EXPECT_EQ(model.edge(model.edgeCount() + 1).index, 0);
    EXPECT_EQ(Model().edgeCount(), 0);
}

TEST(EdgeChains, ShuffledOutlineMakesOneClosedChainInTheFirstEdgesDirection)
{
    const Model model = roundedBlock();
    std::vector<int> edges = outlineEdgesAt(model, 10);
    ASSERT_EQ(edges.size(), 8u);
    std::mt19937 random(7);
    for (int round = 0; round < 5; ++round) {
        std::shuffle(edges.begin(), edges.end(), random);
        const geom::Profile chain = oneChain(model, edges);
        ASSERT_FALSE(chain.empty());
        EXPECT_TRUE(chain.closed);
        EXPECT_NEAR(std::abs(chain.signedArea()), 50 * 30 - (4 - kPi) * 16, 1e-6);
        EXPECT_EQ(test::countSegments(chain).arcs, 4);
        EXPECT_EQ(test::countSegments(chain).lines, 4);
        const EdgeInfo first = model.edge(edges.front());
        EXPECT_TRUE(near(chain.segments.front().start, first.start.xy()));
        EXPECT_TRUE(near(chain.segments.front().end, first.end.xy()));
    }
}

TEST(EdgeChains, OpenChainRunsThroughTheFirstEdge)
{
    const Model model = roundedBlock();
    const std::vector<int> outline = outlineEdgesAt(model, 10);
    // An arc and the two lines touching it, listed arc first.
    int arc = 0;
    for (int i : outline)
        if (model.edge(i).curve == Curve::Circle)
            arc = i;
    ASSERT_GT(arc, 0);
    const EdgeInfo a = model.edge(arc);
    std::vector<int> picked = {arc};
    for (int i : outline) {
        const EdgeInfo e = model.edge(i);
        if (e.curve == Curve::Line && (near(e.start.xy(), a.start.xy()) || near(e.end.xy(), a.start.xy()) ||
                                       near(e.start.xy(), a.end.xy()) || near(e.end.xy(), a.end.xy())))
            picked.push_back(i);
    }
    ASSERT_EQ(picked.size(), 3u);
    const geom::Profile chain = oneChain(model, picked);
    EXPECT_FALSE(chain.closed);
    ASSERT_EQ(chain.segments.size(), 3u);
    EXPECT_FALSE(chain.segments[0].isArc());
    ASSERT_TRUE(chain.segments[1].isArc());
    EXPECT_TRUE(near(chain.segments[1].start, a.start.xy()));
    EXPECT_TRUE(near(chain.segments[1].end, a.end.xy()));
    EXPECT_NEAR(chain.segments[1].radius(), 4, 1e-9);
    double length = 0;
    for (int i : picked)
        length += model.edge(i).lengthMm;
    EXPECT_NEAR(chain.length(), length, 1e-9);
}

TEST(EdgeChains, SeveralChainsAndAFullCircle)
{
    const Model model = roundedBlock();
    std::vector<int> edges = outlineEdgesAt(model, 10);
    const std::vector<int> bottom = outlineEdgesAt(model, 0);
    edges.insert(edges.end(), bottom.begin(), bottom.end());
    int circle = 0;
    for (int i = 1; i <= model.edgeCount(); ++i)
        if (model.edge(i).curve == Curve::Circle && std::abs(model.edge(i).start.z - 10) < 1e-9 &&
            distance(model.edge(i).start.xy(), base::Vec2{25, 15}) < 3.5)
            circle = i;
    ASSERT_GT(circle, 0);
    edges.push_back(circle);
    const auto chains = model.edgeChains(edges);
    ASSERT_TRUE(chains.ok()) << chains.error().toString();
    ASSERT_EQ(chains->size(), 3u);
    for (const geom::Profile& chain : chains.value()) {
        EXPECT_TRUE(chain.closed);
        EXPECT_TRUE(chain.isContinuous(1e-9));
    }
    const geom::Profile& hole = chains->back();
    ASSERT_EQ(hole.segments.size(), 2u);  // a full circle as two half arcs
    EXPECT_NEAR(std::abs(hole.signedArea()), kPi * 9, 1e-9);
    for (const geom::Segment& s : hole.segments)
        EXPECT_TRUE(s.isArc() && near(s.center, {25, 15}));
}

std::string chainError(const Model& model, const std::vector<int>& edges)
{
    const auto chains = model.edgeChains(edges);
    return chains.ok() ? std::string("ok") : chains.error().message;
}

TEST(EdgeChains, Errors)
{
    const Model model = roundedBlock();
    const std::vector<int> outline = outlineEdgesAt(model, 10);
    int vertical = 0;
    for (int i = 1; i <= model.edgeCount(); ++i)
        if (model.edge(i).curve == Curve::Line && std::abs(model.edge(i).start.z - model.edge(i).end.z) > 1)
            vertical = i;
    ASSERT_GT(vertical, 0);

    EXPECT_EQ(chainError(model, {0}), "edge 0 does not exist (the model has 27 edges)");
    EXPECT_NE(chainError(model, {outline[0], model.edgeCount() + 1}).find("does not exist"), std::string::npos);
    EXPECT_EQ(chainError(model, {outline[0], outline[1], outline[0]}),
              "edge " + std::to_string(outline[0]) + " is selected twice");
    EXPECT_EQ(chainError(model, {outline[0], vertical}),
              "edge " + std::to_string(vertical) + " is vertical: only edges in an XY plane can be chained");
    EXPECT_EQ(chainError(model, {}), "no edges selected");
    EXPECT_NE(model.edgeChains(outline, 0).ok(), true);
}

TEST(EdgeChains, BranchingIsRefused)
{
    // Two boxes fused side by side: the top has a dividing edge, so three top edges meet at (10, 0, 5).
    const Model model =
        test::loadShape(test::fuse(test::box(0, 0, 0, 10, 10, 5), test::box(10, 0, 0, 20, 10, 5)), "two-boxes");
    std::vector<int> top;
    for (int i = 1; i <= model.edgeCount(); ++i)
        if (std::abs(model.edge(i).start.z - 5) < 1e-9 && std::abs(model.edge(i).end.z - 5) < 1e-9)
            top.push_back(i);
    ASSERT_EQ(top.size(), 7u);
    const std::string message = chainError(model, top);
    EXPECT_NE(message.find("meet at one point"), std::string::npos) << message;
    EXPECT_NE(message.find("a chain cannot branch"), std::string::npos) << message;
}

TEST(EdgeChains, BSplineEdgeIsRefittedWithinTheTolerance)
{
    const double pts[][2] = {{0, 0}, {10, 8}, {20, 14}, {35, 10}, {50, 0}};
    Handle(TColgp_HArray1OfPnt) points = new TColgp_HArray1OfPnt(1, 5);
    for (int i = 0; i < 5; ++i)
        points->SetValue(i + 1, gp_Pnt(pts[i][0], pts[i][1], 0));
    GeomAPI_Interpolate interpolate(points, Standard_False, 1e-9);
    interpolate.Perform();
    const Handle(Geom_BSplineCurve) spline = interpolate.Curve();
    BRepBuilderAPI_MakeWire wire(BRepBuilderAPI_MakeEdge(spline).Edge());
    wire.Add(BRepBuilderAPI_MakeEdge(gp_Pnt(50, 0, 0), gp_Pnt(0, 0, 0)).Edge());
    const TopoDS_Face face = BRepBuilderAPI_MakeFace(wire.Wire(), Standard_True).Face();
    const Model model = test::loadShape(BRepPrimAPI_MakePrism(face, gp_Vec(0, 0, 4)).Shape(), "bspline-chain");

    int top = 0;
    for (int i = 1; i <= model.edgeCount(); ++i)
        if (model.edge(i).curve == Curve::BSpline && std::abs(model.edge(i).start.z - 4) < 1e-9)
            top = i;
    ASSERT_GT(top, 0);
    const double tolerance = 0.005;
    const geom::Profile chain = oneChain(model, {top}, tolerance);
    ASSERT_FALSE(chain.empty());
    EXPECT_FALSE(chain.closed);
    EXPECT_TRUE(near(chain.segments.front().start, model.edge(top).start.xy()));
    EXPECT_TRUE(near(chain.segments.back().end, model.edge(top).end.xy()));
    for (int i = 0; i <= 1000; ++i) {
        const double u = spline->FirstParameter() + (spline->LastParameter() - spline->FirstParameter()) * i / 1000;
        const gp_Pnt p = spline->Value(u);
        ASSERT_LE(geom::distanceToProfile({p.X(), p.Y()}, chain), tolerance) << "at u = " << u;
    }
    EXPECT_NEAR(chain.length(), model.edge(top).lengthMm, 0.01);
}

}  // namespace
}  // namespace camwb::occ
