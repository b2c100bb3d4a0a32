// Every Klartext listing of the references (tests/data/nc/heidenhain, transcribed verbatim) reads
// without errors; fragments cut with "..." give warnings only; the thesis arc of seed-000 §4.1
// traces with start and end radius agreeing within 0.001 mm.
#include "TestSupport.h"

#include "base/AtomicFile.h"

#include <cmath>
#include <numbers>

namespace camwb::nc::heidenhain::test {
namespace {

using namespace camwb::toolpath;

std::string listing(const std::string& name)
{
    const std::string path = std::string(CAMWB_TEST_DATA_DIR) + "/tests/data/nc/heidenhain/" + name;
    auto text = base::readTextFile(path);
    EXPECT_TRUE(text) << path;
    return text ? text.value() : std::string();
}

// The listings are figures cut out of programs, most without the moves before them: they start
// at the origin.
Traced runListing(const std::string& name)
{
    InterpretOptions options = fromOrigin();
    options.fileName = name;
    options.arcRadiusToleranceMm = 0.001;
    return run(listing(name), options);
}

struct Expectation {
    const char* file;
    std::vector<std::string> diagnostics;  // "line:column: severity: message"
};

TEST(HeidenhainReferenceListings, EveryListingReadsWithoutErrors)
{
    const std::string elided = "warning: lines left out here ('...'): the listing is a fragment";
    const Expectation cases[] = {
        {"seed-000-fig3-3-linear-circular.h", {"1:0: warning: feed motion with no feed programmed"}},
        {"seed-000-fig5-1-header.h", {}},
        {"seed-000-fig5-3-tool-change.h", {"1:1: " + elided, "8:1: " + elided}},
        {"seed-000-fig5-4-first-moves.h",
         {"1:1: " + elided, "2:32: warning: spindle started with no speed (S) programmed", "5:1: " + elided}},
        {"seed-000-fig5-5-circle.h",
         {"1:1: " + elided,
          "3:4: warning: the circle's start point is unknown (no X and Y programmed before it): radius not checked",
          "3:0: warning: feed motion with no feed programmed", "4:1: " + elided}},
        {"seed-000-fig5-6-program-end.h", {"1:1: " + elided, "5:1: " + elided}},
        {"seed-000-fig5-7-parametric-feed.h", {"1:1: " + elided, "5:1: " + elided, "8:1: " + elided}},
        {"seed-000-fig5-8-cycle-200.h",
         {"9:8: warning: decimal comma read as a decimal point",
          "10:20: warning: spindle started with no speed (S) programmed",
          "11:3: warning: cycle depth is positive: traced as the same depth below the surface (the control "
          "machines upwards or refuses it, depending on its machine parameters)"}},
        {"seed-000-fig5-9-travels.h", {}},
        {"seed-000-fig5-10-tool-list.h", {}},
    };
    for (const Expectation& c : cases) {
        const Traced r = runListing(c.file);
        EXPECT_EQ(r.count(Severity::Error), 0u) << c.file;
        EXPECT_EQ(r.diagnostics(), c.diagnostics) << c.file;
        EXPECT_TRUE(r.result.completed) << c.file;
    }
}

TEST(HeidenhainReferenceListings, ThesisArcRadiiAgreeWithinAMicron)
{
    // seed-000 §4.1: from (-48.915, -74.568) about CC (-54.254, -66.113), counter-clockwise.
    const Traced r = runListing("seed-000-fig3-3-linear-circular.h");
    const auto lines = r.all<Linear>();
    const auto arcs = r.all<Arc>();
    ASSERT_EQ(lines.size(), 1u);
    ASSERT_EQ(arcs.size(), 1u);
    const Vec3 start = lines[0].to;
    const Arc& arc = arcs[0];
    expectNear(start, {-48.915, -74.568, 0});
    expectNear(arc.center, {-54.254, -66.113, 0});
    expectNear(arc.to, {-45.799, -60.773, 0});
    EXPECT_FALSE(arc.clockwise);
    const double startRadius = distance(start.xy(), arc.center.xy());
    const double endRadius = distance(arc.to.xy(), arc.center.xy());
    EXPECT_NEAR(startRadius, 9.9996, 0.00005);
    EXPECT_NEAR(endRadius, 10.0001, 0.00005);
    EXPECT_LE(std::abs(startRadius - endRadius), 0.001);
    const base::Vec2 a = start.xy() - arc.center.xy(), b = arc.to.xy() - arc.center.xy();
    const double sweep = std::atan2(a.cross(b), a.dot(b)) * 180 / std::numbers::pi;
    EXPECT_NEAR(sweep, 90.005, 0.001);
    EXPECT_EQ(r.lines<Arc>(), std::vector<int>{3});
}

TEST(HeidenhainReferenceListings, ThesisArcWithTheFeedsOfFig57)
{
    // Figs. 5.7 and 3.3 are one program: with Q602 = 1500 the arc runs at the finishing feed.
    const std::string text = "0 BEGIN PGM F MM\n33 Q602=1500 ;dokoncovaci\n" +
                             listing("seed-000-fig3-3-linear-circular.h") + "47 END PGM F MM\n";
    InterpretOptions options = fromOrigin();
    options.arcRadiusToleranceMm = 0.001;
    const Traced r = run(text, options);
    EXPECT_TRUE(r.result.diagnostics.empty()) << r.diagnostics()[0];
    ASSERT_EQ(r.all<Arc>().size(), 1u);
    EXPECT_EQ(r.all<Arc>()[0].feedMmPerMin, 1500);
}

TEST(HeidenhainReferenceListings, ToolChangeAndFirstMovesTraceInOrder)
{
    const Traced tool = runListing("seed-000-fig5-3-tool-change.h");
    ASSERT_EQ(tool.all<ToolChange>().size(), 1u);
    EXPECT_EQ(tool.all<ToolChange>()[0].tool.number, 1);
    EXPECT_EQ(tool.lines<ToolChange>(), std::vector<int>{7});
    EXPECT_EQ(tool.all<Comment>().size(), 5u);

    const Traced moves = runListing("seed-000-fig5-4-first-moves.h");
    const auto rapids = moves.all<Rapid>();
    ASSERT_EQ(rapids.size(), 2u);
    expectNear(rapids[0].to, {-49.048, -74.356, 0});
    expectNear(rapids[1].to, {-49.048, -74.356, 150});
    EXPECT_EQ(moves.all<Coolant>()[0].mode, CoolantMode::Flood);
    EXPECT_EQ(moves.lines<Coolant>(), std::vector<int>{3});
    EXPECT_EQ(moves.all<Comment>()[0].text, "Kapalina");
}

TEST(HeidenhainReferenceListings, ProgramEndStopsAtM30)
{
    const Traced r = runListing("seed-000-fig5-6-program-end.h");
    ASSERT_EQ(r.all<Rapid>().size(), 1u);
    expectNear(r.all<Rapid>()[0].to, {0, 0, 333});
    EXPECT_TRUE(r.result.completed);
}

TEST(HeidenhainReferenceListings, Cycle200ListingGivesTwoHoles)
{
    const Traced r = runListing("seed-000-fig5-8-cycle-200.h");
    const auto cycles = r.all<Cycle>();
    ASSERT_EQ(cycles.size(), 2u);
    expectNear(cycles[0].holes[0], {20, 30, 0});
    expectNear(cycles[1].holes[0], {50, 30, 0});
    EXPECT_EQ(cycles[0].dwellSeconds, 0.25);
    EXPECT_EQ(cycles[0].clearanceZ, 50);
}

}  // namespace
}  // namespace camwb::nc::heidenhain::test
