// The turning checks on NC programs read back by the SINUMERIK interpreter: the seed-001 groove
// subprograms (Šolar 2015, tests/data/nc/seed-001) on the shaft they groove, against the offset
// contour of seed REQ-15, and small hand-written programs with a known fault at a known line.
#include "geom/RegionOps.h"
#include "nc/Interpreter.h"
#include "sim/TurningCheck.h"
#include "sim/TurningProfile.h"
#include "toolpath/Toolpath.h"
#include "toolpath/ToolpathRecorder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>

namespace camwb::sim {
namespace {

std::string dataDir() { return std::string(CAMWB_TEST_DATA_DIR) + "/tests/data/nc/seed-001"; }

std::string readFile(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

struct Traced {
    nc::InterpretResult result;
    toolpath::Toolpath path;
};

// KOD5.MPF calling the reconstructed programs (seed §4.3), with some of Kod 1's input blocks
// replaced (e.g. {"N08 R3=170", "N08 R3=160"}).
Traced traceSeed(const std::map<std::string, std::string>& replace = {})
{
    const nc::ProgramResolver folder = nc::folderResolver(dataDir() + "/reconstructed", {".SPF"});
    nc::InterpretOptions options;
    options.dialect = nc::Dialect::Sinumerik;
    options.fileName = dataDir() + "/KOD5.MPF";
    options.resolveProgram = [folder, replace](std::string_view name) {
        auto source = folder(name);
        if (source && name == "PODPROG_ZAPICH")
            for (const auto& [from, to] : replace) {
                const auto at = source->text.find(from);
                EXPECT_NE(at, std::string::npos) << from;
                if (at != std::string::npos)
                    source->text.replace(at, from.size(), to);
            }
        return source;
    };
    toolpath::ToolpathRecorder recorder;
    Traced t;
    t.result = nc::interpret(readFile(options.fileName), options, recorder);
    t.path = recorder.take();
    EXPECT_TRUE(t.result.completed);
    EXPECT_FALSE(t.result.hasErrors());
    return t;
}

TurningReport checkSeed(const Traced& t, const GrooveParameters& g)
{
    TurningOptions options;
    options.insert.widthMm = g.r9;
    return checkTurning(t.path, grooveStock(g), grooveOffsetPart(g), options);
}

// "PODPROG_DNO_ZP.SPF:12" for each finding of `kind`.
std::vector<std::string> where(const TurningReport& report, const Traced& traced, CheckKind kind)
{
    std::vector<std::string> out;
    for (const Check& f : report.findings)
        if (f.kind == kind) {
            const toolpath::SourceRef& source = traced.path.source(static_cast<std::size_t>(f.record));
            const std::string& file = traced.result.files[static_cast<std::size_t>(source.file)];
            out.push_back(file.substr(file.find_last_of('/') + 1) + ":" + std::to_string(source.line));
        }
    return out;
}

// The thesis' own program (Kod 1) ends through PODPROG_DNO_ZL, as its SinuTrain run did: no rapid
// touches the stock, nothing of the offset contour is cut, and what is left is the offset part
// itself (seed REQ-15 a, b, d: the roughing leaves no material above the offset contour).
TEST(TurningSeed001, ThesisProgramCutsTheGrooveWithoutRapidHitsOrGouges)
{
    const Traced t = traceSeed();
    const GrooveParameters g;
    const TurningReport r = checkSeed(t, g);
    // 575 traced moves: Kod 5's G0 X=R0+200 and N72 G0 Z start where Z is not known yet (the
    // second, making the position whole, leaves the tool standing at its end: a move of no
    // length), and 7 of the others have no length.
    EXPECT_EQ(r.moves, 567u);
    EXPECT_TRUE(where(r, t, CheckKind::RapidInStock).empty());
    EXPECT_TRUE(where(r, t, CheckKind::Gouge).empty());
    EXPECT_FALSE(r.hasErrors());
    EXPECT_NEAR(r.maxRapidDepthMm, 0, 1e-3);
    EXPECT_EQ(r.feedsInAir, 8u);  // counted and named once (the first: ZL line 41, G1 to the cleared flank top)
    ASSERT_EQ(r.findings.size(), 1u);
    EXPECT_EQ(r.findings[0].kind, CheckKind::AirCutting);
    EXPECT_EQ(r.findings[0].severity, base::Severity::Note);
    const TurningRegion part = grooveOffsetPart(g);
    EXPECT_NEAR(geom::totalArea(geom::subtract(r.stock, part, 1e-4)), 0, 0.01);  // nothing left over
    EXPECT_NEAR(geom::totalArea(geom::subtract(part, r.stock, 1e-4)), 0, 0.01);  // nothing gouged
    EXPECT_NEAR(r.removedMm2, geom::totalArea(grooveStock(g)) - geom::totalArea(part), 0.01);
}

// Seed §5.3 item 1: with R3 = 160 the program ends through PODPROG_DNO_ZP, whose bottom sweep
// programs right-corner Z values as the left corner: the insert goes R9 into the right flank.
// Gouge R9/tan(R5) = 25.4994 mm (issue 17's figure); two rapids run into the flank: N130 G0 Z=R15
// (5.4994 mm: the retract height is 20 mm above the bottom, the flank rises 25.4994 over the
// insert's width) and N180 G0 Z=R20 (22.9261 mm, the seed's strip model samples 22.89 there).
TEST(TurningSeed001, DnoZpGougesTheRightFlankAndRapidsThroughStock)
{
    const Traced t = traceSeed({{"N08 R3=170", "N08 R3=160"}});
    GrooveParameters g;
    g.r3 = 160;
    const TurningReport r = checkSeed(t, g);
    EXPECT_EQ(where(r, t, CheckKind::RapidInStock),
              (std::vector<std::string>{"PODPROG_DNO_ZP.SPF:31", "PODPROG_DNO_ZP.SPF:42"}));
    std::vector<double> rapidDepths;
    for (const Check& f : r.findings)
        if (f.kind == CheckKind::RapidInStock) {
            rapidDepths.push_back(f.valueMm);
            EXPECT_EQ(f.severity, base::Severity::Error);
        }
    ASSERT_EQ(rapidDepths.size(), 2u);
    EXPECT_NEAR(rapidDepths[0], 5.4994, 1e-3);
    EXPECT_NEAR(rapidDepths[1], 22.9261, 1e-3);
    // 27: the half-step plunge already 1.57 mm right of T; 31, 42: the rapids; 32, 43, 44: the
    // plunge at T, the plunge at B and the slide from B to T, all with the insert beyond T.
    EXPECT_EQ(where(r, t, CheckKind::Gouge),
              (std::vector<std::string>{"PODPROG_DNO_ZP.SPF:27", "PODPROG_DNO_ZP.SPF:31", "PODPROG_DNO_ZP.SPF:32",
                                        "PODPROG_DNO_ZP.SPF:42", "PODPROG_DNO_ZP.SPF:43", "PODPROG_DNO_ZP.SPF:44"}));
    const double expected = g.r9 / std::tan(g.r5 * std::numbers::pi / 180);
    EXPECT_NEAR(expected, 25.4994, 1e-4);
    EXPECT_NEAR(r.maxGougeMm, expected, 1e-3);
    EXPECT_NEAR(r.maxGougeAt.y, g.r0 - g.r3 + g.r7, 1e-3);  // the insert on the bottom offset
    EXPECT_TRUE(r.hasErrors());
}

// Seed §2.2: with no safety distance (R30 = 0) the example is still free of rapid collisions:
// the rapids run exactly along the surfaces the plunges left, touching but not cutting.
TEST(TurningSeed001, NoSafetyDistanceStillTouchesOnly)
{
    const Traced t = traceSeed({{"N17 R30=1", "N17 R30=0"}});
    const TurningReport r = checkSeed(t, {});
    EXPECT_FALSE(r.hasErrors());
    EXPECT_TRUE(where(r, t, CheckKind::RapidInStock).empty());
    EXPECT_NEAR(r.maxRapidDepthMm, 0, 1e-6);
}

// Seed §5.3 item 7: R10 = 1.2 steps further than the insert is wide; the thesis' retract heights
// assume overlap, so the ZP sweeps rapid through the ribs left standing (the seed: a 41.9 mm G0
// hit in ZP, 28.8 mm² left over), and the run ends through the faulty PODPROG_DNO_ZP.
TEST(TurningSeed001, StepBeyondTheInsertWidthRapidsThroughTheRibs)
{
    const Traced t = traceSeed({{"N15 R10=0.8", "N15 R10=1.2"}});
    const TurningReport r = checkSeed(t, {});
    EXPECT_NEAR(r.maxRapidDepthMm, 41.9195, 1e-3);
    ASSERT_FALSE(r.findings.empty());
    EXPECT_EQ(where(r, t, CheckKind::RapidInStock).front(), "PODPROG_ZP.SPF:4");  // G0 Z=R20-R9-R10*R9*R18
    EXPECT_NEAR(r.findings.front().valueMm, 41.9195, 1e-3);
    EXPECT_EQ(r.rapidsInStock, 133u);
    EXPECT_NEAR(geom::totalArea(geom::subtract(r.stock, grooveOffsetPart({}), 1e-4)), 28.791, 0.01);
    EXPECT_NEAR(r.maxGougeMm, 25.4994, 1e-3);
}

// A shaft of radius 50 (Z 0..100) with a groove to radius 40 between Z 40 and 49.
TurningRegion shaft() { return parseProfileRectangle("0,0,50,100").value(); }
TurningRegion groovedPart()
{
    return parseProfilePoints("50,0\n50,40\n40,40\n40,49\n50,49\n50,100\n", "part.txt").value();
}

struct CheckedProgram {
    toolpath::Toolpath path;
    TurningReport report;
    int lineOf(const Check& f) const { return path.source(static_cast<std::size_t>(f.record)).line; }
};

CheckedProgram checkProgram(const std::string& program, TurningOptions options = {})
{
    nc::InterpretOptions io;
    io.dialect = nc::Dialect::Sinumerik;
    io.fileName = "GROOVE.MPF";
    toolpath::ToolpathRecorder recorder;
    const nc::InterpretResult result = nc::interpret(program, io, recorder);
    EXPECT_FALSE(result.hasErrors());
    CheckedProgram out;
    out.path = recorder.take();
    out.report = checkTurning(out.path, shaft(), groovedPart(), options);
    return out;
}

// Three plunges of a 3 mm insert side by side from an approach outside the stock.
std::string cleanGroove(const std::string& plungeTo = "X40", const std::string& thirdStep = "G0 Z46")
{
    return "G18 G90 G95 F0.1\n"  // 1
           "G0 X60 Z40\n"        // 2
           "G1 X40\n"            // 3
           "G0 X55\n"            // 4
           "G0 Z43\n"            // 5
           "G1 X40\n"            // 6
           "G0 X55\n"            // 7
           + thirdStep +
           "\n"  // 8
           "G1 " +
           plungeTo +
           "\n"        // 9
           "G0 X60\n"  // 10
           "M30\n";
}

TEST(TurningChecks, CleanGrooveReportsNothing)
{
    const TurningReport r = checkProgram(cleanGroove()).report;
    EXPECT_TRUE(r.findings.empty());
    EXPECT_NEAR(r.removedMm2, 9 * 10, 1e-3);  // the groove, 9 wide, 10 deep
    EXPECT_EQ(r.feedsInAir, 0u);
}

TEST(TurningChecks, RapidThroughStockIsReportedAtItsLine)
{
    // Line 8 goes back in at the bottom of the first slot instead of over the stock.
    const CheckedProgram checked = checkProgram(cleanGroove("X40", "G0 X40\nG0 Z46"));
    const TurningReport& r = checked.report;
    ASSERT_EQ(r.rapidsInStock, 1u);
    const Check& f = r.findings.front();
    EXPECT_EQ(f.kind, CheckKind::RapidInStock);
    EXPECT_EQ(f.severity, base::Severity::Error);
    EXPECT_EQ(checked.lineOf(f), 9);  // G0 Z46 from the bottom at Z43 through the uncut Z 46..49
    EXPECT_NEAR(f.valueMm, 10, 1e-3);
    EXPECT_EQ(r.gouges, 0u);
    EXPECT_EQ(r.feedsInAir, 0u);  // the plunge after it is already at X40: no move
}

TEST(TurningChecks, PlungeTooDeepIsAGougeAtItsLine)
{
    const CheckedProgram checked = checkProgram(cleanGroove("X39.5"));
    const TurningReport& r = checked.report;
    ASSERT_EQ(r.gouges, 1u);
    EXPECT_EQ(checked.lineOf(r.findings.front()), 9);
    EXPECT_NEAR(r.maxGougeMm, 0.5, 1e-3);
    EXPECT_EQ(r.rapidsInStock, 0u);
}

// The interpreter halves X under DIAMON, so a diameter program is checked as its radius twin.
TEST(TurningChecks, DiameterProgramsAreHalvedByTheInterpreter)
{
    std::string diameter = "DIAMON\n" + cleanGroove("X79");  // 0.5 mm too deep on the radius
    for (const auto& [from, to] : {std::pair{"X60 ", "X120 "}, {"X55", "X110"}, {"X60\n", "X120\n"}})
        for (std::size_t at = diameter.find(from); at != std::string::npos; at = diameter.find(from, at + 1))
            diameter.replace(at, std::strlen(from), to);
    diameter.replace(diameter.find("G1 X40"), 6, "G1 X80");
    diameter.replace(diameter.find("G1 X40"), 6, "G1 X80");
    const TurningReport r = checkProgram(diameter).report;
    EXPECT_EQ(r.rapidsInStock, 0u);
    ASSERT_EQ(r.gouges, 1u);
    EXPECT_NEAR(r.maxGougeMm, 0.5, 1e-3);
    EXPECT_NEAR(r.removedMm2, 9 * 10 + 3 * 0.5, 1e-3);
}

// A toolpath whose X is a diameter (not from an interpreter) is halved on request.
TEST(TurningChecks, XIsDiameterHalvesX)
{
    toolpath::Toolpath path;
    path.add(toolpath::Rapid({120, 0, 40}));
    path.add(toolpath::Linear({80, 0, 40}, 0.1));
    TurningOptions options;
    options.xIsDiameter = true;
    const TurningReport r = checkTurning(path, shaft(), groovedPart(), options);
    EXPECT_NEAR(r.removedMm2, 30, 1e-3);
    EXPECT_TRUE(r.findings.empty());
}

}  // namespace
}  // namespace camwb::sim
