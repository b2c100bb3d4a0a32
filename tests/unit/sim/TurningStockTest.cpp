// The turning stock's geometry: the insert's sweep, the areas and depths it removes, the gouge
// depth against a design contour, the stock profiles from text and the seed-001 groove's points.
#include "sim/TurningStock.h"
#include "sim/TurningProfile.h"

#include "geom/RegionOps.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

namespace camwb::sim {
namespace {

TurningRegion rectangle(const std::string& spec) { return parseProfileRectangle(spec).value(); }

// The Minkowski sum of a w x h rectangle and a segment (dz, dx): w*h + |dx|*w + |dz|*h.
TEST(TurningStock, SweepOfTheInsertIsTheHullOfItsTwoPlacements)
{
    Insert insert;
    insert.widthMm = 3;
    const auto a = insertOutline(insert, {10, 20}, 5, 1e-4);
    auto points = a;
    const auto b = insertOutline(insert, {14, 22}, 5, 1e-4);
    points.insert(points.end(), b.begin(), b.end());
    const auto hull = convexHull(points);
    EXPECT_EQ(hull.size(), 6u);
    double twice = 0;
    for (std::size_t i = 0; i < hull.size(); ++i)
        twice += hull[i].cross(hull[(i + 1) % hull.size()]);
    EXPECT_NEAR(twice / 2, 3 * 5 + 2 * 3 + 4 * 5, 1e-9);
    // A move of no length, and points on the edges: the rectangle's four corners.
    auto same = a;
    same.insert(same.end(), a.begin(), a.end());
    same.push_back({11, 20});
    EXPECT_EQ(convexHull(same).size(), 4u);
}

TEST(TurningStock, PlungeRemovesWidthTimesDepth)
{
    TurningStock stock(rectangle("0,0,50,100"), {});
    Insert insert;
    insert.widthMm = 3;
    const TurningCut cut = stock.cut(turningPoint(60, 40), turningPoint(42, 40), insert);
    EXPECT_NEAR(cut.removedMm2, 3 * 8, 1e-6);
    EXPECT_NEAR(cut.depthMm, 8, 1e-6);
    EXPECT_NEAR(geom::totalArea(stock.stock()), 5000 - 24, 1e-6);
    // The same plunge again cuts air.
    EXPECT_NEAR(stock.cut(turningPoint(60, 40), turningPoint(42, 40), insert).removedMm2, 0, 1e-6);
}

TEST(TurningStock, CornerRadiiLeaveTheirCorners)
{
    TurningStock stock(rectangle("0,0,50,100"), {});
    Insert insert;
    insert.widthMm = 4;
    insert.cornerRadiusMm = 1;
    const TurningCut cut = stock.cut(turningPoint(60, 40), turningPoint(42, 40), insert);
    // Two corners of (1 - pi/4) r^2 stay, less the chords' error.
    EXPECT_NEAR(cut.removedMm2, 4 * 8 - 2 * (1 - std::numbers::pi / 4), 1e-3);
    EXPECT_NEAR(cut.depthMm, 8, 1e-3);  // in the middle the edge is flat
}

TEST(TurningStock, GougeIsTheRadialDepthBelowTheDesign)
{
    // Design: the shaft with a shoulder rising at 45 degrees from (Z 40, X 40) to (Z 50, X 50).
    const TurningRegion design = parseProfilePoints("40,0\n40,40\n50,50\n50,100\n").value();
    TurningStock stock(rectangle("0,0,50,100"), design);
    Insert insert;
    insert.widthMm = 3;
    const TurningCut cut = stock.cut(turningPoint(60, 41), turningPoint(40, 41), insert);
    EXPECT_NEAR(cut.gougeMm, 4, 1e-4);  // at the right edge Z 44 the shoulder is at X 44
    EXPECT_NEAR(cut.gougeAt.x, 44, 1e-4);
    EXPECT_NEAR(cut.gougeAt.y, 40, 1e-4);
    EXPECT_NEAR(cut.depthMm, 10, 1e-4);
}

TEST(TurningProfile, RectangleAndPointErrors)
{
    EXPECT_NEAR(geom::totalArea(rectangle("50,100,0,0")), 5000, 1e-9);
    EXPECT_FALSE(parseProfileRectangle("1,2,3").ok());
    EXPECT_NE(parseProfileRectangle("-1,0,5,10").error().message.find("negative"), std::string::npos);
    EXPECT_FALSE(parseProfileRectangle("1,2,1,5").ok());
    EXPECT_FALSE(parseProfileRectangle("1,2,x,5").ok());
    const auto bad = parseProfilePoints("; bar\n50,0\n50;100\nfoo\n", "bar.txt");
    ASSERT_FALSE(bad.ok());  // "50;100" is "50" after the comment: one number
    EXPECT_EQ(bad.error().toString().substr(0, 10), "bar.txt:3:");
    EXPECT_EQ(parseProfilePoints("50,0\n-1,4\n", "p").error().line, 2);
    EXPECT_FALSE(parseProfilePoints("50,0\n", "p").ok());
    EXPECT_FALSE(parseProfilePoints("0,0\n0,10\n", "p").ok());  // on the axis: no area
    // A bar outline from left to right is closed along the axis.
    EXPECT_NEAR(geom::totalArea(parseProfilePoints("20,0\n20,10 # shoulder\n30,10\n30,40\n").value()),
                20 * 10 + 30 * 30, 1e-9);
    EXPECT_FALSE(stockProfileFromArgument("/nonexistent/profile.txt").ok());
    const std::string file = (std::filesystem::temp_directory_path() / "camwb-turning-profile.txt").string();
    std::ofstream(file) << "# bar\n25,-5\n25 60\n";
    EXPECT_NEAR(geom::totalArea(stockProfileFromArgument(file).value()), 25 * 65, 1e-9);
    std::ofstream(file) << "25,-5\n25,60,3\n";
    EXPECT_EQ(stockProfileFromArgument(file).error().toString(), file + ":2: expected X,Z (radius, Z in mm)");
    std::filesystem::remove(file);
    EXPECT_NEAR(geom::totalArea(stockProfileFromArgument("0,0,10,10").value()), 100, 1e-9);
}

// Seed REQ-03: the offset corners of the Kod 1 groove.
TEST(TurningProfile, Seed001GrooveGeometry)
{
    const GrooveGeometry g = grooveGeometry({});
    const auto near = [](Vec2 p, double z, double x) {
        EXPECT_NEAR(p.x, z, 1e-6);
        EXPECT_NEAR(p.y, x, 1e-6);
    };
    near(g.r, 110.476352, 150.191159);
    near(g.s, 120.465033, 10.5);
    near(g.t, 164.554886, 10.5);
    near(g.u, 184.471690, 179.788680);
    EXPECT_NEAR(g.c1.x, 109.9890, 1e-4);  // seed §2.1 gives C1 to four decimals
    EXPECT_NEAR(g.c1.y, 149.9962, 1e-4);
    near(g.bottomRight, 164.999509, 10);
    // The offset part is the stock less the area between the surface and the offset contour.
    EXPECT_LT(geom::totalArea(grooveOffsetPart({})), geom::totalArea(grooveStock({})));
}

}  // namespace
}  // namespace camwb::sim
